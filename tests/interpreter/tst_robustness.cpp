// Broken programs never crash the compiler or the VM: every program of a small corpus is mutated
// token by token (deleted, doubled, swapped with its neighbour, replaced) and compiled; whatever
// compiles runs a few cycles. The same mutations go through the project model too (IEC text read
// into the model, printed back, compiled from the model). Under ASan/UBSan any memory error fails
// the test.
#include "interpreter/compiler/compiler.h"
#include "interpreter/compiler/lexer.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include <QTest>

using namespace iec::interp;

namespace {

const char *const kPrograms[] = {
    "TYPE Pt : STRUCT x : INT; y : REAL := 1.5; END_STRUCT; Color : (Red, Green); END_TYPE\n"
    "FUNCTION Twice : INT VAR_INPUT v : INT; END_VAR Twice := v * 2; END_FUNCTION\n"
    "PROGRAM Main\nVAR a : ARRAY[1..4] OF INT := [1, 2(3)]; p : Pt; c : Color; t : TON; s : STRING[8]; i : INT; w : "
    "WORD; END_VAR\n"
    "FOR i := 1 TO 4 DO a[i] := Twice(a[i]) MOD 7; END_FOR;\n"
    "IF a[2] > 3 THEN p.x := a[1]; ELSIF c = Red THEN c := Green; ELSE p.y := p.y * 2.0; END_IF;\n"
    "CASE i OF 1..3: s := CONCAT(s, 'x'); ELSE s := LEFT(s, 2); END_CASE;\n"
    "t(IN := NOT t.Q, PT := T#20ms); w.3 := t.Q;\n"
    "WHILE i > 0 DO i := i - 1; END_WHILE;\nEND_PROGRAM\n",
    "PROGRAM Main\nVAR x : INT; y : BOOL; ERG : INT; c : CTU; END_VAR\n"
    "LD 5\nMUL (6\nADD 7\n)\nST ERG\nLD y\nJMPC skip\nCAL c(CU := TRUE, PV := 3)\nskip:\nLD c.Q\nST y\nEND_PROGRAM\n",
    "PROGRAM Main\nVAR x : BOOL; END_VAR\nINITIAL_STEP S1: A1(N); END_STEP\nTRANSITION FROM S1 TO S2 := x; "
    "END_TRANSITION\n"
    "STEP S2: END_STEP\nACTION A1: x := NOT x; END_ACTION\nEND_PROGRAM\n"
    "CONFIGURATION C\nTASK T(INTERVAL := T#10ms, PRIORITY := 1);\nPROGRAM P WITH T : Main;\nEND_CONFIGURATION\n",
};

// Tokens of `source` (comments kept out), as (offset, length).
std::vector<Token> tokensOf(const QString &source)
{
    std::vector<Token> out;
    for (const Token &t : tokenize(source)) {
        if (t.kind != TokenKind::Comment)
            out.push_back(t);
    }
    return out;
}

void run(const std::shared_ptr<const Module> &module, int &compiled)
{
    if (!module)
        return;
    ++compiled;
    Runtime runtime(module);
    runtime.vm().budgetPerRun = 20'000;
    runtime.runCycles(3);
}

void compileAndRun(const QString &source, int &compiled)
{
    Diagnostics diagnostics;
    run(compileText(source, diagnostics), compiled);
}

void throughTheModel(const QString &source, int &compiled)
{
    const frontend::TextReadResult read = frontend::readIecText(source, QStringLiteral("p"));
    frontend::printProject(read.project);
    Diagnostics diagnostics;
    run(frontend::compileProject(read.project, diagnostics), compiled);
}

// Every token deleted, doubled, replaced and swapped with the next one.
QStringList mutations(const QString &source)
{
    static const char *const replacements[]
        = {":=", ";", "(", ")", "END_IF", "x", "1.5", "'s'", "T#1s", "[", ",", "..", "NOT"};
    QStringList variants;
    const auto tokens = tokensOf(source);
    for (size_t i = 0; i < tokens.size(); ++i) {
        const Token &t = tokens[i];
        const QString before = source.left(t.offset), token = source.mid(t.offset, t.length),
                      after = source.mid(t.offset + t.length);
        variants << before + after << before + token + QLatin1Char(' ') + token + after
                 << before + QString::fromUtf8(replacements[i % std::size(replacements)]) + after;
        if (i + 1 < tokens.size()) {
            const Token &n = tokens[i + 1];
            variants << before + source.mid(n.offset, n.length)
                    + source.mid(t.offset + t.length, n.offset - t.offset - t.length) + token
                    + source.mid(n.offset + n.length);
        }
    }
    return variants;
}

} // namespace

class TestRobustness : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void mutatedProgramsNeverCrash();
    void mutatedProgramsThroughTheModelNeverCrash();
};

void TestRobustness::mutatedProgramsNeverCrash()
{
    int attempts = 0, compiled = 0;
    for (const char *program : kPrograms) {
        for (const QString &variant : mutations(QString::fromUtf8(program))) {
            ++attempts;
            compileAndRun(variant, compiled);
        }
    }
    // The mutations must reach both the error paths and the code generator.
    QVERIFY2(attempts > 600, qPrintable(QString::number(attempts)));
    QVERIFY2(compiled > 20, qPrintable(QString::number(compiled)));
    QVERIFY2(compiled < attempts, qPrintable(QString::number(compiled)));
}

void TestRobustness::mutatedProgramsThroughTheModelNeverCrash()
{
    int attempts = 0, compiled = 0;
    for (const char *program : kPrograms) {
        for (const QString &variant : mutations(QString::fromUtf8(program))) {
            ++attempts;
            throughTheModel(variant, compiled);
        }
    }
    QVERIFY2(compiled > 20, qPrintable(QString::number(compiled)));
    QVERIFY2(compiled < attempts, qPrintable(QString::number(compiled)));
}

QTEST_GUILESS_MAIN(TestRobustness)
#include "tst_robustness.moc"
