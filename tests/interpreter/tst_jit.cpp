// The JIT (interpreter/vm/jit.h) runs programs exactly like the interpreter: after every cycle the
// whole memory image is byte for byte the same, and faults stop at the same POU, line and cycle.
// Each program is run twice from one compiled module, once with IEC_JIT=0.
#include "interpreter/compiler/compiler.h"
#include "interpreter/runtime/runtime.h"
#include "interpreter/vm/jit.h"

#include <QRandomGenerator>
#include <QTest>

using namespace iec::interp;

namespace {

struct Outcome {
    QString problem;           // empty: both runs agreed
    std::size_t translated = 0; // instructions the JIT ran natively
    QString fault;             // how both runs ended: a fault's text, or "no fault"
};

// Sets IEC_JIT=0 for the lifetime of the object.
class InterpreterOnly
{
public:
    InterpreterOnly() { qputenv("IEC_JIT", "0"); }
    ~InterpreterOnly() { qunsetenv("IEC_JIT"); }
};

QString faultText(const Runtime &runtime)
{
    return runtime.fault() ? runtime.fault()->toString() : QStringLiteral("no fault");
}

// Which variable byte `at` of the image belongs to, for messages: "Main.q" or "a temporary".
QString whereIs(const Module &module, std::size_t at)
{
    for (const Symbol &s : module.symbols) {
        if (!s.type || at < s.offset || at >= s.offset + s.type->size)
            continue;
        for (const Member &m : s.type->members) {
            if (m.type && at >= s.offset + m.offset && at < s.offset + m.offset + m.type->size)
                return s.name + QLatin1Char('.') + m.name;
        }
        return s.name;
    }
    return QStringLiteral("a temporary or constant");
}

// Runs `cycles` cycles with and without the JIT, comparing after each one.
Outcome compareRuns(const QString &source, int cycles, std::uint64_t budget = 50'000'000)
{
    Outcome outcome;
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    if (!module || diagnostics.hasErrors()) {
        QStringList errors;
        for (const Diagnostic &d : diagnostics.all())
            errors << d.toString();
        outcome.problem = QStringLiteral("does not compile: ") + errors.join(QStringLiteral(" | "));
        return outcome;
    }
    Runtime jitted(module);
    std::unique_ptr<Runtime> interpreted;
    {
        InterpreterOnly off;
        interpreted = std::make_unique<Runtime>(module);
    }
    outcome.translated = jitted.vm().nativeInstructions();
    if (interpreted->vm().nativeInstructions() != 0) {
        outcome.problem = QStringLiteral("IEC_JIT=0 did not switch the JIT off");
        return outcome;
    }
    jitted.vm().budgetPerRun = budget;
    interpreted->vm().budgetPerRun = budget;
    for (int cycle = 1; cycle <= cycles; ++cycle) {
        const bool ranJitted = jitted.runCycle();
        const bool ranInterpreted = interpreted->runCycle();
        if (ranJitted != ranInterpreted || faultText(jitted) != faultText(*interpreted)) {
            outcome.problem = QStringLiteral("cycle %1: JIT: %2, interpreter: %3").arg(cycle).arg(faultText(jitted), faultText(*interpreted));
            return outcome;
        }
        const auto &a = jitted.vm().memory();
        const auto &b = interpreted->vm().memory();
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (a[i] != b[i]) {
                outcome.problem = QStringLiteral("cycle %1: byte %2 (%5) is %3 with the JIT, %4 without")
                                      .arg(cycle)
                                      .arg(i)
                                      .arg(a[i])
                                      .arg(b[i])
                                      .arg(whereIs(*module, i));
                return outcome;
            }
        }
        if (!ranJitted)
            break;
    }
    outcome.fault = faultText(jitted);
    return outcome;
}

QString program(const char *declarations, const char *body)
{
    return QStringLiteral("PROGRAM Main\nVAR\n%1\nEND_VAR\n%2\nEND_PROGRAM\n").arg(QString::fromUtf8(declarations), QString::fromUtf8(body));
}

} // namespace

class TestJit : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void sameAsInterpreter_data();
    void sameAsInterpreter();
    void randomProgramsRunTheSame();
    void switchedOffRunsNothingNatively();
};

void TestJit::initTestCase()
{
    qunsetenv("IEC_JIT");
    if (!jitEnabled())
        QSKIP("The JIT is only built for x86-64 Linux; the interpreter runs everything here.");
}

void TestJit::sameAsInterpreter_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<int>("cycles");
    QTest::addColumn<QString>("fault"); // the fault both runs must end with, or empty

    QTest::newRow("integer wraparound, every type")
        << program("s : SINT; i : INT; d : DINT; l : LINT; us : USINT; ui : UINT; ud : UDINT; ul : ULINT; k : INT;",
                   "FOR k := 1 TO 50 DO\n s := s + 7; i := i * 3 + 1; d := d * 7 - 3; l := l * 5 + k;\n"
                   " us := us - 3; ui := ui * 5 + 1; ud := ud * 9 + 7; ul := ul * 13 + 5;\n"
                   " s := -s; i := -i; l := l - LINT#1000000000000;\nEND_FOR;")
        << 4 << QString();
    QTest::newRow("division and MOD: signs, -1, MIN")
        << program("a : DINT := -2147483648; b : DINT; q : ARRAY[0..20] OF DINT; r : ARRAY[0..20] OF DINT; k : INT;\n"
                   "x : SINT := -128; y : SINT; z : SINT; li : LINT := -9223372036854775807; lq : LINT; lr : LINT;\n"
                   "u : UDINT := 4000000000; uq : UDINT; ur : UDINT; ul : ULINT := 18000000000000000000; ulq : ULINT;",
                   "FOR k := 0 TO 20 DO\n b := k - 10;\n IF b <> 0 THEN q[k] := a / b; r[k] := (a + k) MOD b; END_IF;\n"
                   " y := x / SINT#-1; z := x MOD SINT#-1; lq := (li - 1) / LINT#-1; lr := li MOD LINT#-7;\n"
                   " uq := u / UDINT#7; ur := u MOD UDINT#7; ulq := ul / ULINT#3;\nEND_FOR;")
        << 3 << QString();
    QTest::newRow("division by zero stops at the same line")
        << program("d : DINT; k : DINT;", "FOR k := 5 TO -5 BY -1 DO\n  d := d + 100 / k;\nEND_FOR;")
        << 3 << QStringLiteral("Main:6: Integer division by zero. (cycle 1)");
    QTest::newRow("comparisons of every integer type")
        << program("s : SINT; us : USINT; i : INT; ud : UDINT; l : LINT; ul : ULINT; k : INT; c : ARRAY[0..11] OF BOOL; n : DINT;",
                   "FOR k := -3 TO 3 DO\n s := INT_TO_SINT(k * 50); us := INT_TO_USINT(k * 50); i := k * 20000; ud := INT_TO_UDINT(k) * 1500000000;\n"
                   " l := INT_TO_LINT(k) * 4000000000; ul := LINT_TO_ULINT(l);\n"
                   " c[0] := s < SINT#10; c[1] := us >= USINT#100; c[2] := i <= 0; c[3] := ud > UDINT#2000000000;\n"
                   " c[4] := l = LINT#0; c[5] := ul > ULINT#9000000000000000000; c[6] := s <> SINT#0; c[7] := ul <= ULINT#4000000000;\n"
                   " c[8] := ud < UDINT#10; c[9] := l >= LINT#-4000000000; c[10] := us = USINT#150; c[11] := i > 30000;\n"
                   " IF c[3] THEN n := n + 1; END_IF; IF ul > ULINT#9000000000000000000 THEN n := n + 10; END_IF;\n"
                   " IF ud >= UDINT#3000000000 THEN n := n + 100; END_IF;\nEND_FOR;")
        << 2 << QString();
    QTest::newRow("REAL and LREAL, NaN compares false")
        << program("r : REAL; lr : LREAL; n : REAL; nl : LREAL; k : INT; t : ARRAY[0..15] OF BOOL; acc : LREAL; neg : REAL;",
                   "n := SQRT(-1.0); nl := SQRT(LREAL#-1.0);\n"
                   "FOR k := 0 TO 9 DO\n r := r * 1.5 + INT_TO_REAL(k) / 3.0; lr := lr - REAL_TO_LREAL(r) * 0.25; acc := acc + lr / 7.0;\n"
                   " neg := -r; r := r / 1.25;\n"
                   " t[0] := n = n; t[1] := n <> n; t[2] := n < r; t[3] := n <= r; t[4] := n > r; t[5] := n >= r;\n"
                   " t[6] := r > 2.0; t[7] := lr < -1.0; t[8] := nl = nl; t[9] := nl <> nl; t[10] := r = r; t[11] := acc <= lr;\n"
                   " t[12] := LREAL_TO_REAL(acc) >= r; t[13] := neg < 0.0;\n"
                   " IF n < r THEN acc := acc + 1000.0; END_IF; IF n <> n THEN acc := acc + 0.5; END_IF;\n"
                   " IF lr >= -2.0 THEN acc := acc - 0.125; END_IF;\nEND_FOR;")
        << 3 << QString();
    QTest::newRow("conversions between elementary types")
        << program("k : DINT; si : SINT; ud : UDINT; b : BYTE; w : WORD; lw : LWORD; r : REAL; lr : LREAL; li : LINT; i : INT; us : USINT;",
                   "FOR k := -300 TO 300 BY 37 DO\n si := DINT_TO_SINT(k); ud := SINT_TO_UDINT(si); b := SINT_TO_BYTE(si); w := DINT_TO_WORD(k * 300);\n"
                   " lw := DINT_TO_LWORD(k); r := DINT_TO_REAL(k) / 7.0; lr := REAL_TO_LREAL(r); r := LREAL_TO_REAL(lr * 3.0);\n"
                   " li := UDINT_TO_LINT(ud); i := LINT_TO_INT(li * 1000); us := BYTE_TO_USINT(b); lr := LINT_TO_LREAL(li) + UDINT_TO_LREAL(ud);\nEND_FOR;")
        << 2 << QString();
    QTest::newRow("two-dimensional array with offset bounds")
        << program("m : ARRAY[1..5, -2..2] OF INT; i : INT; j : INT; s : DINT;",
                   "FOR i := 1 TO 5 DO FOR j := -2 TO 2 DO m[i, j] := i * 10 + j; END_FOR; END_FOR;\n"
                   "s := 0; FOR i := 5 TO 1 BY -1 DO FOR j := 2 TO -2 BY -1 DO s := s + m[i, j] * i; END_FOR; END_FOR;")
        << 2 << QString();
    QTest::newRow("index out of range stops at the same line")
        << program("a : ARRAY[0..9] OF DINT; k : INT;", "FOR k := 0 TO 10 DO\n  a[k] := k;\nEND_FOR;")
        << 2 << QStringLiteral("Main:6: Array index out of range. (cycle 1)");
    QTest::newRow("WHILE, REPEAT and EXIT")
        << program("i : DINT; j : DINT; n : DINT; found : DINT;",
                   "i := 0; WHILE i < 1000 DO i := i + 3; IF i MOD 17 = 0 THEN EXIT; END_IF; END_WHILE;\n"
                   "j := 100; REPEAT j := j - 7; n := n + 1; UNTIL j < 0 END_REPEAT;\n"
                   "FOR i := 1 TO 100 DO FOR j := 1 TO 100 DO IF i * j = 391 THEN found := i; EXIT; END_IF; END_FOR; IF found <> 0 THEN EXIT; END_IF; END_FOR;")
        << 3 << QString();
    QTest::newRow("bit strings and bit access")
        << program("w : WORD := 16#F00F; d : DWORD := 16#12345678; lw : LWORD; b : BYTE; k : INT; bits : ARRAY[0..15] OF BOOL;",
                   "FOR k := 0 TO 15 DO\n bits[k] := w.3 XOR d.17; w := w XOR DINT_TO_WORD(k * 4097); d := (d AND 16#0FF0FF0F) OR INT_TO_DWORD(k);\n"
                   " lw := NOT lw XOR DWORD_TO_LWORD(d); b := NOT b AND 16#5A; bits[15 - k] := lw.63 OR b.1;\nEND_FOR;")
        << 2 << QString();
    QTest::newRow("CASE in a loop")
        << program("k : INT; a : DINT; b : DINT; c : DINT;",
                   "FOR k := 0 TO 40 DO\n CASE k MOD 9 OF\n 0: a := a + 1;\n 1, 2: b := b + k;\n 3..5: c := c - k;\n ELSE a := a * 2 - b;\n END_CASE;\nEND_FOR;")
        << 2 << QString();
    QTest::newRow("rungs: long boolean lists")
        << program("a0 : BOOL := TRUE; a1 : BOOL; a2 : BOOL := TRUE; a3 : BOOL; b0 : BOOL; b1 : BOOL := TRUE; b2 : BOOL; b3 : BOOL;\n"
                   "o0 : BOOL; o1 : BOOL; o2 : BOOL; o3 : BOOL; o4 : BOOL; o5 : BOOL; o6 : BOOL; o7 : BOOL; n : INT;",
                   "n := n + 1; a1 := n MOD 2 = 0; b3 := n MOD 3 = 0;\n"
                   "o0 := (a0 AND NOT b0) OR (a1 AND o7);\no1 := (a1 AND NOT b1) OR (a2 AND o0);\no2 := (a2 AND NOT b2) OR (a3 AND o1);\n"
                   "o3 := (a3 AND NOT b3) OR (a0 AND o2);\no4 := (o3 OR a1) AND NOT b3;\no5 := o4 AND o3 OR b2;\n"
                   "o6 := NOT o5 AND (o4 OR o0);\no7 := (o6 AND NOT o1) OR (o2 AND o3);\n"
                   "a0 := NOT a0; b0 := o7; a2 := o6 XOR o5; a3 := a3 OR o4;\n"
                   "IF o7 THEN b2 := NOT b2; END_IF;\nIF NOT o1 AND o2 THEN b1 := FALSE; ELSE b1 := TRUE; END_IF;")
        << 12 << QString();
    QTest::newRow("timers: straight line and in an FB")
        << program("t0 : TON; t1 : TON; t2 : TOF; t3 : TP; t4 : TON; t5 : TON; q : ARRAY[0..5] OF BOOL; et : ARRAY[0..5] OF TIME; n : INT; run : BOOL;",
                   "n := n + 1; run := n MOD 13 < 9;\n"
                   "t0(IN := run, PT := T#30ms); q[0] := t0.Q; et[0] := t0.ET;\nt1(IN := NOT run, PT := T#20ms); q[1] := t1.Q; et[1] := t1.ET;\n"
                   "t2(IN := run, PT := T#40ms); q[2] := t2.Q; et[2] := t2.ET;\nt3(IN := run, PT := T#50ms); q[3] := t3.Q; et[3] := t3.ET;\n"
                   "t4(IN := q[0], PT := T#10ms); q[4] := t4.Q; et[4] := t4.ET;\nt5(IN := q[4] OR q[2], PT := T#70ms); q[5] := t5.Q; et[5] := t5.ET;")
        << 40 << QString();
    QTest::newRow("subrange fault stops at the same line")
        << QStringLiteral("TYPE Pct : INT (0..100); END_TYPE\nPROGRAM Main\nVAR p : Pct; k : INT; END_VAR\n"
                          "FOR k := 1 TO 30 DO\n  p := p + 1;\nEND_FOR;\nEND_PROGRAM\n")
        << 5 << QStringLiteral("Main:5: A value outside the subrange of its type was assigned. (cycle 4)");
    QTest::newRow("an endless loop stops at the same place")
        << program("i : DINT; j : DINT;", "WHILE TRUE DO\n  i := i + 1; j := j - i;\nEND_WHILE;")
        << 2 << QStringLiteral("Main:5: The program ran too long in one cycle; is there an endless loop? (cycle 1)");
    QTest::newRow("function block instances with their own loops")
        << QStringLiteral("FUNCTION_BLOCK Acc\nVAR_INPUT n : DINT; END_VAR\nVAR_OUTPUT sum : DINT; END_VAR\nVAR k : DINT; hist : ARRAY[0..7] OF DINT; END_VAR\n"
                          "FOR k := 1 TO n DO sum := sum + k; hist[k MOD 8] := hist[k MOD 8] + sum; END_FOR;\nEND_FUNCTION_BLOCK\n"
                          "PROGRAM Main\nVAR a : Acc; b : Acc; x : DINT; y : DINT; i : INT; END_VAR\n"
                          "FOR i := 1 TO 3 DO a(n := 10 * i); b(n := i); END_FOR; x := a.sum; y := b.sum;\nEND_PROGRAM\n")
        << 3 << QString();
    QTest::newRow("globals and a global array next to the program's own loop")
        << QStringLiteral("VAR_GLOBAL g : ARRAY[0..31] OF DINT; gs : DINT; gr : LREAL; END_VAR\n"
                          "PROGRAM Main\nVAR_EXTERNAL g : ARRAY[0..31] OF DINT; gs : DINT; gr : LREAL; END_VAR\nVAR k : DINT; own : DINT; END_VAR\n"
                          "FOR k := 0 TO 31 DO g[k] := g[k] + k * own; gs := gs + g[k]; own := own + 1; gr := gr + DINT_TO_LREAL(gs) / 3.0; END_FOR;\nEND_PROGRAM\n")
        << 3 << QString();
    QTest::newRow("REAL matrix product")
        << program("a : ARRAY[0..35] OF REAL; b : ARRAY[0..35] OF REAL; c : ARRAY[0..35] OF REAL; i : DINT; j : DINT; k : DINT; sum : REAL; ld : ARRAY[0..5] OF LREAL;",
                   "FOR i := 0 TO 35 DO a[i] := DINT_TO_REAL(i MOD 7) * 0.5 + c[i]; b[i] := DINT_TO_REAL(i MOD 5) - 1.0; END_FOR;\n"
                   "FOR i := 0 TO 5 DO FOR j := 0 TO 5 DO sum := 0.0; FOR k := 0 TO 5 DO sum := sum + a[i * 6 + k] * b[k * 6 + j]; END_FOR;\n"
                   " c[i * 6 + j] := sum; ld[j] := ld[j] + REAL_TO_LREAL(sum); END_FOR; END_FOR;")
        << 3 << QString();
    // Rows added by the JIT review (jitrev): cases the rows above do not reach.
    QTest::newRow("FOR on SINT that wraps never ends")
        << program("s : SINT; n : DINT;", "FOR s := 120 TO 127 DO\n  n := n + 1;\nEND_FOR;")
        << 2 << QStringLiteral("Main:5: The program ran too long in one cycle; is there an endless loop? (cycle 1)");
    QTest::newRow("USINT FOR that wraps, counted against the budget")
        << program("us : USINT; m : DINT; l : LINT;", "FOR us := 250 TO 255 DO\n  m := m + 1; l := l + m;\nEND_FOR;")
        << 2 << QStringLiteral("Main:5: The program ran too long in one cycle; is there an endless loop? (cycle 1)");
    QTest::newRow("MIN / -1 and MOD -1 of SINT, INT, DINT from variables; bits of negative values")
        << program("i : INT := -32768; m : INT := -1; q : INT; r : INT; us : USINT := 250; ud : USINT; w : UINT := 65535; wq : UINT; k : INT;\n"
                   "s : SINT := -128; sm : SINT := -1; sq : SINT; sr : SINT; d : DINT := -2147483648; dm : DINT := -1; dq : DINT; dr : DINT;\n"
                   "b1 : BOOL; b2 : BOOL; b3 : BOOL; b4 : BOOL; b5 : BOOL; lq : LINT := -5;",
                   "FOR k := 1 TO 5 DO\n q := i / m; r := i MOD m; sq := s / sm; sr := s MOD sm; dq := d / dm; dr := d MOD dm;\n"
                   " ud := us / USINT#7 + us MOD INT_TO_USINT(k); wq := w / INT_TO_UINT(k) + w MOD INT_TO_UINT(k + 3);\n"
                   " b1 := i.15; b2 := s.7; b3 := lq.63; b4 := q.0; b5 := w.15; lq := lq * 3;\nEND_FOR;")
        << 2 << QString();
    QTest::newRow("a timer called in a loop: cached variables live across the call")
        << program("t : TON; k : DINT; a : DINT; b : DINT; c : DINT; l : LINT; n : DINT; r : REAL; q : BOOL; x : LREAL;",
                   "FOR k := 1 TO 20 DO\n t(IN := k MOD 3 <> 0, PT := T#0ms);\n"
                   " a := a + k; b := b + a; c := c * 3 + b; l := l + a; r := r + 1.5; x := x * 1.01 + 1.0;\n"
                   " IF t.Q THEN n := n + 1; END_IF;\n q := t.Q;\nEND_FOR;")
        << 5 << QString();
    QTest::newRow("a function block writes its own instance through a global")
        << QStringLiteral("FUNCTION_BLOCK Acc\nVAR_EXTERNAL g : Acc; END_VAR\nVAR_INPUT inc : DINT; END_VAR\nVAR_OUTPUT sum : DINT; END_VAR\nVAR k : DINT; END_VAR\n"
                          "FOR k := 1 TO 10 DO sum := sum + k + inc; g.inc := g.inc + sum; inc := inc * 2; END_FOR;\nEND_FUNCTION_BLOCK\n"
                          "VAR_GLOBAL g : Acc; END_VAR\nPROGRAM Main\nVAR x : DINT; y : DINT; END_VAR\ng(); x := g.sum; y := g.inc;\nEND_PROGRAM\n")
        << 3 << QString();
    QTest::newRow("a jump into a run of packed rungs")
        << program("a : BOOL := TRUE; b : BOOL; c : BOOL := TRUE; d : BOOL; e : BOOL; f : BOOL := TRUE; n : INT;\n"
                   "o0 : BOOL; o1 : BOOL; o2 : BOOL; o3 : BOOL; o4 : BOOL; o5 : BOOL; o6 : BOOL; o7 : BOOL; o8 : BOOL; o9 : BOOL;",
                   "n := n + 1; a := n MOD 2 = 0; b := n MOD 3 = 0; d := n MOD 5 < 2;\n"
                   "IF a THEN\no0 := (a AND NOT b) OR (c AND o9);\no1 := (b AND NOT c) OR (o0 AND d);\nEND_IF;\n"
                   "o2 := (c AND NOT d) OR (o1 AND a);\no3 := (d AND NOT o2) OR (o2 AND b);\no4 := (o3 AND NOT a) OR (o3 AND c);\n"
                   "o5 := (o4 AND NOT b) OR (o4 AND d);\no6 := (o5 AND NOT c) OR (o5 AND f);\no7 := (o6 AND NOT o0) OR (o6 AND a);\n"
                   "o8 := (o7 AND NOT o1) OR (o7 AND e);\no9 := (o8 AND NOT o2) OR (o8 AND b);\ne := NOT e;")
        << 12 << QString();
    QTest::newRow("structure arrays, INT index arithmetic, a function and FB instances with loops")
        << QStringLiteral("TYPE P : STRUCT x : DINT; y : REAL; f : BOOL; END_STRUCT; END_TYPE\n"
                          "FUNCTION Sum3 : DINT\nVAR_INPUT n : DINT; END_VAR\nVAR k : DINT; acc : DINT; END_VAR\n"
                          "acc := 0; FOR k := 1 TO n DO acc := acc + k * k; END_FOR; Sum3 := acc;\nEND_FUNCTION\n"
                          "FUNCTION_BLOCK Acc\nVAR_INPUT n : INT; END_VAR\nVAR_OUTPUT sum : DINT; END_VAR\nVAR k : INT; m : ARRAY[0..49] OF INT; t : TON; END_VAR\n"
                          "FOR k := 0 TO n DO m[k MOD 5 * 10 + k MOD 10] := m[k MOD 5 * 10 + k MOD 10] + k; sum := sum + m[(k MOD 5) * 10 + 3];\n"
                          " t(IN := k MOD 2 = 0, PT := T#0ms); IF t.Q THEN sum := sum + 1; END_IF; END_FOR;\nEND_FUNCTION_BLOCK\n"
                          "PROGRAM Main\nVAR pts : ARRAY[0..9] OF P; a : Acc; b : Acc; i : INT; j : INT; s : DINT; r : REAL; g : ARRAY[0..99] OF DINT; fs : DINT; END_VAR\n"
                          "FOR i := 0 TO 9 DO pts[i].x := pts[i].x + i * 3; pts[i].y := pts[i].y + INT_TO_REAL(i) * 0.5; pts[i].f := NOT pts[i].f;\n"
                          " s := s + pts[i].x; r := r + pts[i].y; END_FOR;\n"
                          "FOR i := 0 TO 9 DO FOR j := 0 TO 9 DO g[i * 10 + j] := g[i * 10 + j] + i - j; s := s + g[i * 10 + j]; END_FOR; END_FOR;\n"
                          "a(n := 20); b(n := 7); fs := Sum3(10) + Sum3(INT_TO_DINT(i));\nEND_PROGRAM\n")
        << 5 << QString();
    QTest::newRow("more accumulators than registers, then a subrange fault")
        << QStringLiteral("TYPE Pct : INT (0..100); END_TYPE\nPROGRAM Main\n"
                          "VAR p : Pct; k : INT; a : DINT; b : DINT; c : DINT; d : DINT; e : DINT; f : DINT; g : DINT; h : DINT; i : DINT; j : DINT; m : DINT; x : LREAL; y : REAL; END_VAR\n"
                          "FOR k := 1 TO 40 DO\n  a := a + k; b := b + a; c := c + b; d := d + c; e := e - d; f := f + e; g := g + f; h := h + g; i := i + h; j := j + i; m := m + j;\n"
                          "  x := x * 1.5 + y; y := y + 0.25;\n  p := k * 3;\nEND_FOR;\nEND_PROGRAM\n")
        << 2 << QStringLiteral("Main:7: A value outside the subrange of its type was assigned. (cycle 1)");
}

void TestJit::sameAsInterpreter()
{
    QFETCH(QString, source);
    QFETCH(int, cycles);
    QFETCH(QString, fault);
    const Outcome outcome = compareRuns(source, cycles, 1'000'000);
    QCOMPARE(outcome.problem, QString());
    QVERIFY2(outcome.translated > 0, "the JIT translated nothing of this program");
    if (!fault.isEmpty()) // both runs faulted alike (compareRuns): is it the fault the row is about?
        QCOMPARE(outcome.fault, fault);
}

namespace {

// Random programs over integer, real and boolean variables: assignments, IF, FOR, WHILE and array
// accesses, each statement in one type (IEC has no implicit narrowing).
class RandomProgram
{
public:
    explicit RandomProgram(quint32 seed)
        : m_random(seed)
    {
    }

    QString generate()
    {
        QString body;
        for (int i = 0, n = 3 + pick(5); i < n; ++i)
            body += statement(0);
        QString declarations;
        for (const auto &[name, type] : kVariables)
            declarations += QStringLiteral("%1 : %2;\n").arg(QLatin1String(name), QLatin1String(type));
        declarations += QStringLiteral("arr : ARRAY[-3..12] OF DINT; k1 : DINT; k2 : DINT; guard : DINT;\n");
        return QStringLiteral("PROGRAM Main\nVAR\n%1END_VAR\nguard := 0;\n%2END_PROGRAM\n").arg(declarations, body);
    }

private:
    struct Variable {
        const char *name;
        const char *type;
    };
    static constexpr Variable kVariables[] = {{"s1", "SINT"},  {"s2", "SINT"},  {"i1", "INT"},    {"i2", "INT"},    {"d1", "DINT"},
                                              {"d2", "DINT"},  {"d3", "DINT"},  {"l1", "LINT"},   {"us1", "USINT"}, {"ui1", "UINT"},
                                              {"ud1", "UDINT"}, {"ud2", "UDINT"}, {"ul1", "ULINT"}, {"r1", "REAL"},   {"r2", "REAL"},
                                              {"lr1", "LREAL"}, {"b1", "BOOL"},  {"b2", "BOOL"},   {"w1", "WORD"}};

    int pick(int n) { return int(m_random.bounded(n)); }

    QString variableOf(const QString &type)
    {
        QStringList names;
        for (const auto &[name, t] : kVariables) {
            if (type == QLatin1String(t))
                names << QLatin1String(name);
        }
        if (type == QLatin1String("DINT"))
            names << QStringLiteral("arr[%1]").arg(index());
        return names.isEmpty() ? literal(type) : names[pick(int(names.size()))];
    }

    QString index()
    {
        // Mostly in range; sometimes out of it, which faults alike in both runs.
        const int v = pick(20) - 4;
        return pick(3) == 0 ? QStringLiteral("k1 MOD 16 - 3") : QString::number(v < -3 || v > 12 ? v / 2 : v);
    }

    QString literal(const QString &type)
    {
        if (type == QLatin1String("BOOL"))
            return pick(2) ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
        if (type == QLatin1String("REAL") || type == QLatin1String("LREAL"))
            return QStringLiteral("%1#%2.%3").arg(type).arg(pick(200) - 100).arg(pick(100));
        const bool isUnsigned = type.startsWith(QLatin1Char('U')) || type == QLatin1String("WORD");
        const int v = isUnsigned ? pick(300) : pick(300) - 150;
        if (type == QLatin1String("SINT") || type == QLatin1String("USINT"))
            return QStringLiteral("%1#%2").arg(type).arg(isUnsigned ? v % 256 : v % 128);
        return QStringLiteral("%1#%2").arg(type).arg(v);
    }

    QString expression(const QString &type, int depth)
    {
        if (depth > 2 || pick(3) == 0)
            return pick(3) == 0 ? literal(type) : variableOf(type);
        if (type == QLatin1String("BOOL")) {
            static const char *const cmp[] = {"<", "<=", ">", ">=", "=", "<>"};
            static const char *const types[] = {"SINT", "INT", "DINT", "UDINT", "ULINT", "REAL", "LREAL"};
            const QString t = QLatin1String(types[pick(7)]);
            switch (pick(3)) {
            case 0: return QStringLiteral("(%1 %2 %3)").arg(expression(t, depth + 1), QLatin1String(cmp[pick(6)]), expression(t, depth + 1));
            case 1: return QStringLiteral("(%1 AND NOT %2)").arg(expression(type, depth + 1), expression(type, depth + 1));
            default: return QStringLiteral("(%1 %2 %3)").arg(expression(type, depth + 1), QLatin1String(pick(2) ? "OR" : "XOR"), expression(type, depth + 1));
            }
        }
        const bool real = type == QLatin1String("REAL") || type == QLatin1String("LREAL");
        if (type == QLatin1String("WORD"))
            return QStringLiteral("(%1 %2 %3)").arg(expression(type, depth + 1), QLatin1String(pick(2) ? "AND" : "XOR"), expression(type, depth + 1));
        const bool isUnsigned = type.startsWith(QLatin1Char('U')); // and they cannot be negated
        switch (pick(real ? 5 : isUnsigned ? 6 : 7)) {
        case 0: return QStringLiteral("(%1 + %2)").arg(expression(type, depth + 1), expression(type, depth + 1));
        case 1: return QStringLiteral("(%1 - %2)").arg(expression(type, depth + 1), expression(type, depth + 1));
        case 2: return QStringLiteral("(%1 * %2)").arg(expression(type, depth + 1), expression(type, depth + 1));
        case 3: return QStringLiteral("(%1 / %2)").arg(expression(type, depth + 1), expression(type, depth + 1));
        case 4: return conversionInto(type, depth);
        case 5: return QStringLiteral("(%1 MOD %2)").arg(expression(type, depth + 1), expression(type, depth + 1));
        default: return QStringLiteral("(-%1)").arg(expression(type, depth + 1));
        }
    }

    QString conversionInto(const QString &type, int depth)
    {
        static const char *const from[] = {"SINT", "INT", "DINT", "UDINT", "LINT", "USINT"};
        const QString source = QLatin1String(from[pick(6)]);
        if (source == type)
            return variableOf(type);
        return QStringLiteral("%1_TO_%2(%3)").arg(source, type, expression(source, depth + 1));
    }

    QString statement(int depth)
    {
        const int kind = depth > 1 ? 0 : pick(6);
        if (kind == 1)
            return QStringLiteral("IF %1 THEN\n%2ELSE\n%3END_IF;\n").arg(expression(QStringLiteral("BOOL"), 1), statement(depth + 1), statement(depth + 1));
        if (kind == 2)
            return QStringLiteral("FOR k1 := %1 TO %2 BY %3 DO\n%4%5END_FOR;\n")
                .arg(pick(5) - 2)
                .arg(pick(12))
                .arg(pick(3) + 1)
                .arg(statement(depth + 1), statement(depth + 1));
        if (kind == 3)
            return QStringLiteral("k2 := 0;\nWHILE k2 < %1 AND guard < 10000 DO\nk2 := k2 + 1; guard := guard + 1;\n%2END_WHILE;\n")
                .arg(pick(9))
                .arg(statement(depth + 1));
        const Variable &v = kVariables[pick(int(std::size(kVariables)))];
        const QString target = pick(6) == 0 ? QStringLiteral("arr[%1]").arg(index()) : QLatin1String(v.name);
        const QString type = target.startsWith(QLatin1String("arr")) ? QStringLiteral("DINT") : QLatin1String(v.type);
        return QStringLiteral("%1 := %2;\n").arg(target, expression(type, 0));
    }

    QRandomGenerator m_random;
};

} // namespace

void TestJit::randomProgramsRunTheSame()
{
    int translated = 0, compiled = 0;
    for (quint32 seed = 1; seed <= 400; ++seed) {
        const QString source = RandomProgram(seed).generate();
        const Outcome outcome = compareRuns(source, 4, 200'000);
        if (outcome.problem.startsWith(QLatin1String("does not compile"))) {
            if (qEnvironmentVariableIsSet("IEC_JIT_TEST_VERBOSE"))
                qInfo().noquote() << outcome.problem;
            continue; // a random expression the type rules refuse (e.g. a constant division by zero)
        }
        ++compiled;
        translated += outcome.translated > 0 ? 1 : 0;
        QVERIFY2(outcome.problem.isEmpty(), qPrintable(QStringLiteral("seed %1: %2\n%3").arg(seed).arg(outcome.problem, source)));
    }
    // The generator must produce mostly valid programs that the JIT takes, or the test says nothing.
    QVERIFY2(compiled >= 300, qPrintable(QStringLiteral("only %1 programs compiled").arg(compiled)));
    QVERIFY2(translated >= compiled / 2, qPrintable(QStringLiteral("only %1 of %2 programs were translated").arg(translated).arg(compiled)));
}

void TestJit::switchedOffRunsNothingNatively()
{
    const QString source = program("k : DINT; s : DINT;", "FOR k := 1 TO 100 DO s := s + k; END_FOR;");
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QVERIFY(module);
    Runtime on(module);
    QVERIFY(on.vm().nativeInstructions() > 0);
    InterpreterOnly off;
    Runtime interpreted(module);
    QCOMPARE(interpreted.vm().nativeInstructions(), std::size_t(0));
}

QTEST_GUILESS_MAIN(TestJit)
#include "tst_jit.moc"
