// Random well-defined programs (randomprogram.h), each written in ST, in ST with its inputs
// constant (so the compiler folds them) and in IL, each run with the JIT and with the interpreter
// alone: after every cycle the six runs hold the same values, and the JIT's memory image is the
// interpreter's byte for byte.
//
// ctest runs a fixed set of seeds (a few seconds under ASan). For a longer search:
//   IEC_DIFF_PROGRAMS=20000 IEC_DIFF_FIRST_SEED=1000 tst_differential randomProgramsAgree
#include "randomprogram.h"

#include "interpreter/compiler/compiler.h"
#include "interpreter/runtime/runtime.h"
#include "interpreter/vm/jit.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;

namespace {

constexpr int kCycles = 4;

QString errorsText(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all()) {
        if (d.severity == Diagnostic::Severity::Error)
            lines << d.toString();
    }
    return lines.join(QStringLiteral(" | "));
}

// One form of the program, run twice: with the JIT and with the interpreter alone.
struct Form {
    QString name;
    QString source;
    std::shared_ptr<const Module> module;
    std::unique_ptr<Runtime> jitted;
    std::unique_ptr<Runtime> interpreted;
};

QString compileForm(Form &form)
{
    Diagnostics diagnostics;
    form.module = compileText(form.source, diagnostics);
    if (!form.module)
        return QStringLiteral("%1 does not compile: %2").arg(form.name, errorsText(diagnostics));
    form.jitted = std::make_unique<Runtime>(form.module);
    qputenv("IEC_JIT", "0");
    form.interpreted = std::make_unique<Runtime>(form.module);
    qunsetenv("IEC_JIT");
    return {};
}

// Runs the forms cycle by cycle; returns what differed first, or nothing.
QString compare(std::vector<Form> &forms, const QStringList &names)
{
    for (int cycle = 1; cycle <= kCycles; ++cycle) {
        QString reference;
        for (Form &f : forms) {
            for (Runtime *r : {f.jitted.get(), f.interpreted.get()}) {
                if (!r->runCycle())
                    return QStringLiteral("%1 faulted in cycle %2: %3").arg(f.name).arg(cycle).arg(r->fault()->toString());
            }
            if (f.jitted->vm().memory() != f.interpreted->vm().memory())
                return QStringLiteral("%1: the JIT's memory differs from the interpreter's after cycle %2").arg(f.name).arg(cycle);
            QStringList values;
            for (const QString &n : names)
                values << n + QLatin1Char('=') + f.jitted->read(QStringLiteral("Main.") + n).value_or(QStringLiteral("?"));
            const QString line = values.join(QStringLiteral("; "));
            if (reference.isEmpty())
                reference = line;
            else if (line != reference)
                return QStringLiteral("cycle %1:\n  %2: %3\n  %4: %5").arg(cycle).arg(forms.front().name, reference, f.name, line);
        }
    }
    return {};
}

int environmentInt(const char *name, int fallback)
{
    bool ok = false;
    const int v = qEnvironmentVariableIntValue(name, &ok);
    return ok ? v : fallback;
}

} // namespace

class TestDifferential : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void randomProgramsAgree();
};

void TestDifferential::randomProgramsAgree()
{
    const int count = environmentInt("IEC_DIFF_PROGRAMS", 120);
    const int first = environmentInt("IEC_DIFF_FIRST_SEED", 1);
    QStringList failures;
    for (int seed = first; seed < first + count; ++seed) {
        const RandomProgram program(static_cast<quint32>(seed));
        std::vector<Form> forms(3);
        forms[0].name = QStringLiteral("ST");
        forms[0].source = program.st(false);
        forms[1].name = QStringLiteral("ST with constant inputs");
        forms[1].source = program.st(true);
        forms[2].name = QStringLiteral("IL");
        forms[2].source = program.il();
        QString problem;
        for (Form &f : forms) {
            if (problem.isEmpty())
                problem = compileForm(f);
        }
        if (problem.isEmpty())
            problem = compare(forms, program.compared());
        if (!problem.isEmpty()) {
            failures << QStringLiteral("seed %1: %2").arg(seed).arg(problem);
            if (qEnvironmentVariableIsSet("IEC_DIFF_VERBOSE"))
                qInfo().noquote() << failures.back() << "\n" << forms[0].source << "\n" << forms[2].source;
        }
    }
    qInfo().noquote() << QStringLiteral("%1 programs (seeds %2..%3), %4 disagreements").arg(count).arg(first).arg(first + count - 1).arg(failures.size());
    QVERIFY2(failures.isEmpty(), qPrintable(failures.mid(0, 5).join(QLatin1Char('\n'))));
}

QTEST_GUILESS_MAIN(TestDifferential)
#include "tst_differential.moc"
