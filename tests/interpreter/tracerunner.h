#pragma once

// Runs a program cycle by cycle from a compact description, for table-driven tests:
//   each step is "name=value; name=value => name=value; name=value": the values left of "=>"
//   are written before the cycle, those right of it are compared after the cycle. Names are
//   looked up in Main first.

#include "interpreter/compiler/compiler.h"
#include "interpreter/runtime/runtime.h"

#include <QStringList>
#include <QTest>

namespace iec::interp::testing {

// Main.name when Main has such a variable, else the name as given (globals, %QX0.1, Main.x).
inline QString qualified(const Runtime &runtime, const QString &name)
{
    const QString local = QStringLiteral("Main.") + name;
    return runtime.find(local) ? local : name;
}

// The diagnostics (only the errors when `errorsOnly`), as "Pou:line:column: severity: ..."
// joined by " | ".
inline QString diagnosticsText(const Diagnostics &diagnostics, bool errorsOnly)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all()) {
        if (!errorsOnly || d.severity == Diagnostic::Severity::Error)
            lines << d.toString();
    }
    return lines.join(QStringLiteral(" | "));
}

// The errors among `diagnostics`, as "Pou:line:column: error: ..." joined by " | ".
inline QString errorsOf(const Diagnostics &diagnostics)
{
    return diagnosticsText(diagnostics, true);
}

// Runs the steps on `runtime` (see the top of this file). Returns an empty string when every
// expectation held, otherwise what went wrong.
inline QString runSteps(Runtime &runtime, const QStringList &steps)
{
    // "name=value" items; an item without a name and '=' is a typo in the table, reported.
    const auto pairs = [](const QString &text, QString &malformed) {
        QList<QPair<QString, QString>> out;
        for (const QString &item : text.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
            const qsizetype eq = item.indexOf(QLatin1Char('='));
            if (eq > 0)
                out.append({item.left(eq).trimmed(), item.mid(eq + 1).trimmed()});
            else if (!item.trimmed().isEmpty())
                malformed = item.trimmed();
        }
        return out;
    };
    QStringList problems;
    int cycle = 0;
    for (const QString &step : steps) {
        ++cycle;
        const QStringList sides = step.split(QStringLiteral("=>"));
        QString malformed;
        const auto writes = pairs(sides[0], malformed);
        const auto checks = sides.size() > 1 ? pairs(sides[1], malformed) : decltype(writes) {};
        if (sides.size() > 2 || !malformed.isEmpty())
            return QStringLiteral("cycle %1: malformed step '%2'").arg(cycle).arg(step);
        for (const auto &[name, value] : writes) {
            if (const auto problem = runtime.write(qualified(runtime, name), value))
                return QStringLiteral("cycle %1: cannot set %2: %3").arg(cycle).arg(name, *problem);
        }
        if (!runtime.runCycle())
            return QStringLiteral("cycle %1: fault: %2").arg(cycle).arg(runtime.fault()->toString());
        if (sides.size() < 2)
            continue;
        for (const auto &[name, expected] : checks) {
            const auto actual = runtime.read(qualified(runtime, name));
            if (!actual)
                return QStringLiteral("cycle %1: no variable %2").arg(cycle).arg(name);
            if (*actual != expected)
                problems << QStringLiteral("cycle %1: %2 = %3, expected %4").arg(cycle).arg(name, *actual, expected);
        }
    }
    return problems.join(QStringLiteral(" | "));
}

// Returns an empty string when every expectation held, otherwise what went wrong.
inline QString runTrace(const QString &source, const QStringList &steps, const CompileOptions &options = {})
{
    Diagnostics diagnostics;
    const QString program = source.contains(QLatin1String("PROGRAM")) ? source
                                                                     : QStringLiteral("PROGRAM Main\n") + source + QStringLiteral("\nEND_PROGRAM\n");
    const auto module = compileText(program, diagnostics, options);
    if (!module)
        return QStringLiteral("does not compile: ") + errorsOf(diagnostics);
    Runtime runtime(module, options.cycleNs);
    return runSteps(runtime, steps);
}

// Table-driven traces (opt in with `using namespace iec::interp::testing::table;`): a _data
// function calls columns() and adds rows with row() or expr(); the test function calls check().
namespace table {

inline void columns()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QStringList>("steps");
}

inline void row(const char *name, const QByteArray &source, const QStringList &steps)
{
    QTest::newRow(name) << QString::fromUtf8(source) << steps;
}

// A one-cycle row: VAR block declarations, statements, expectations after the cycle.
inline void expr(const char *name, const char *declarations, const char *body, const char *expectations)
{
    row(name, QByteArray("VAR ") + declarations + " END_VAR\n" + body, {QStringLiteral("=> ") + QString::fromUtf8(expectations)});
}

// Runs the row's trace; the test fails with what went wrong.
inline void check()
{
    QFETCH(QString, source);
    QFETCH(QStringList, steps);
    QCOMPARE(runTrace(source, steps), QString());
}

} // namespace table

} // namespace iec::interp::testing
