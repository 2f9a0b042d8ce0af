// Subrange types (TYPE Pct : INT(0..100)): every way a value reaches a subrange variable is
// checked. A constant out of range is a compile error; any other value is checked when it is
// written, and a value out of range stops the program with the POU and line of the write.
#include "tracerunner.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;

namespace {

const char *const kPct = "TYPE Pct : INT (0..100); END_TYPE\n";
const QString kFault = QStringLiteral("A value outside the subrange of its type was assigned.");

} // namespace

class TestSubrange : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void faults_data();
    void faults();
    void valuesInRangePass_data();
    void valuesInRangePass();
    void compileErrors_data();
    void compileErrors();
    void forLoopWarnings_data();
    void forLoopWarnings();
};

// Each row: a program, the cycles to run, the fault expected ("Pou:line" and cycle), and values
// read after the fault: the variable keeps its last value inside the range where it can.
void TestSubrange::faults_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<int>("cycles");
    QTest::addColumn<QString>("fault");
    QTest::addColumn<QString>("checks");
    const auto row = [](const char *name, const QByteArray &source, int cycles, const char *where, int cycle, const char *checks) {
        QTest::newRow(name) << QString::fromUtf8(source) << cycles
                            << QStringLiteral("%1: %2 (cycle %3)").arg(QLatin1String(where), kFault).arg(cycle) << QString::fromUtf8(checks);
    };
    const QByteArray pct(kPct);
    const QByteArray fbIn = pct + "FUNCTION_BLOCK Fb\nVAR_INPUT p : Pct; END_VAR\nVAR_OUTPUT o : INT; END_VAR\no := p;\nEND_FUNCTION_BLOCK\n";
    const QByteArray fnIn = pct + "FUNCTION Fn : INT\nVAR_INPUT p : Pct; END_VAR\nFn := p;\nEND_FUNCTION\n";
    // Lines: 1 TYPE, 2-6 the FB or 2-5 the function; Main follows.
    row("FB input, formal", fbIn + "PROGRAM Main\nVAR x : INT; fb : Fb; END_VAR\nx := x + 60;\nfb(p := x);\nEND_PROGRAM", 5, "Main:10", 2, "x=120; fb.p=60; fb.o=60");
    row("FB input, positional", fbIn + "PROGRAM Main\nVAR x : INT; fb : Fb; END_VAR\nx := x + 60;\nfb(x);\nEND_PROGRAM", 5, "Main:10", 2, "x=120; fb.p=60");
    row("FB input, IL CAL with formal arguments", fbIn + "PROGRAM Main\nVAR x : INT; fb : Fb; END_VAR\nLD x\nADD 60\nST x\nCAL fb(p := x)\nEND_PROGRAM", 5, "Main:12", 2, "x=120; fb.p=60");
    row("FB input, IL input operator", pct + "FUNCTION_BLOCK Fb\nVAR_INPUT PV : Pct; END_VAR\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR x : INT; fb : Fb; END_VAR\nLD x\nADD 60\nST x\nPV fb\nEND_PROGRAM", 5, "Main:10", 2, "x=120; fb.PV=60");
    row("function input, formal", fnIn + "PROGRAM Main\nVAR x : INT; y : INT; END_VAR\nx := x + 60;\ny := Fn(p := x);\nEND_PROGRAM", 5, "Main:9", 2, "x=120; y=60");
    row("function input, positional", fnIn + "PROGRAM Main\nVAR x : INT; y : INT; END_VAR\nx := x + 60;\ny := Fn(x);\nEND_PROGRAM", 5, "Main:9", 2, "x=120; y=60");
    row("function input, IL operand", fnIn + "PROGRAM Main\nVAR x : INT; y : INT; END_VAR\nLD x\nADD 60\nST x\nFn\nST y\nEND_PROGRAM", 5, "Main:11", 2, "x=120; y=60");
    row("FB output with =>", pct + "FUNCTION_BLOCK Fb\nVAR_INPUT i : INT; END_VAR\nVAR_OUTPUT o : INT; END_VAR\no := i;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR x : INT; fb : Fb; q : Pct; END_VAR\nx := x + 60;\nfb(i := x, o => q);\nEND_PROGRAM", 5, "Main:10", 2, "q=60; fb.o=120");
    row("function output with =>", pct + "FUNCTION Fn : BOOL\nVAR_INPUT i : INT; END_VAR\nVAR_OUTPUT o : INT; END_VAR\no := i;\nFn := TRUE;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR x : INT; q : Pct; b : BOOL; END_VAR\nx := x + 60;\nb := Fn(i := x, o => q);\nEND_PROGRAM", 5, "Main:11", 2, "q=60");
    row("VAR_IN_OUT of the base type changes a subrange variable", pct + "FUNCTION Bump : BOOL\nVAR_IN_OUT v : INT; END_VAR\nv := v + 60;\nBump := TRUE;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR q : Pct; b : BOOL; END_VAR\nb := Bump(q);\nEND_PROGRAM", 5, "Main:9", 2, "");
    row("VAR_IN_OUT of a subrange type given a larger value", pct + "FUNCTION Keep : BOOL\nVAR_IN_OUT v : Pct; END_VAR\nKeep := v > 50;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR x : INT; b : BOOL; END_VAR\nx := x + 60;\nb := Keep(v := x);\nEND_PROGRAM", 5, "Main:9", 2, "x=120; b=TRUE");
    row("VAR_IN_OUT of a subrange type written in the callee", pct + "FUNCTION_BLOCK Adder\nVAR_IN_OUT v : Pct; END_VAR\nv := v + 60;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR q : Pct; fb : Adder; END_VAR\nfb(v := q);\nEND_PROGRAM", 5, "Adder:4", 2, "q=60");
    row("function result", pct + "FUNCTION Get : Pct\nVAR_INPUT v : INT; END_VAR\nGet := v;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR x : INT; y : INT; END_VAR\nx := x + 60;\ny := Get(x);\nEND_PROGRAM", 5, "Get:4", 2, "x=120; y=60");
    row("function result stored into a subrange variable", pct + "FUNCTION Twice : INT\nVAR_INPUT v : INT; END_VAR\nTwice := 2 * v;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR x : INT; q : Pct; END_VAR\nx := x + 30;\nq := Twice(x);\nEND_PROGRAM", 5, "Main:9", 2, "x=60; q=60");
    // FOR: the counter is checked on every step, the one past the end value too (CODESYS calls
    // its range check on each step; with a clamping check that loop never ends).
    row("FOR counter passing the end of its subrange", "PROGRAM Main\nVAR i : INT(0..10); n : INT; END_VAR\nn := 0;\nFOR i := 0 TO 10 DO\n  n := n + 1;\nEND_FOR;\nEND_PROGRAM",
        1, "Main:4", 1, "i=10; n=11");
    row("FOR counter with a step known at run time", "PROGRAM Main\nVAR i : INT(0..10); n : INT; s : INT := 4; END_VAR\nn := 0;\nFOR i := 0 TO 10 BY s DO\n  n := n + 1;\nEND_FOR;\nEND_PROGRAM",
        1, "Main:4", 1, "i=8; n=3");
    row("FOR counter downwards", "PROGRAM Main\nVAR i : INT(1..10); n : INT; END_VAR\nn := 0;\nFOR i := 10 TO 1 BY -3 DO\n  n := n + 1;\nEND_FOR;\nEND_PROGRAM",
        1, "Main:4", 1, "i=1; n=4");
    row("FOR start value", "PROGRAM Main\nVAR i : INT(0..10); k : INT := 8; n : INT; END_VAR\nk := k + 2;\nFOR i := k TO 5 DO\n  n := n + 1;\nEND_FOR;\nEND_PROGRAM",
        5, "Main:4", 2, "i=10; k=12; n=0");
    row("WHILE counter", "PROGRAM Main\nVAR i : INT(0..10); END_VAR\ni := 0;\nWHILE i < 20 DO\n  i := i + 3;\nEND_WHILE;\nEND_PROGRAM", 1, "Main:5", 1, "i=9");
    row("REPEAT counter", "PROGRAM Main\nVAR i : INT(0..10); END_VAR\ni := 0;\nREPEAT\n  i := i + 4;\nUNTIL i > 10 END_REPEAT;\nEND_PROGRAM", 1, "Main:5", 1, "i=8");
    row("IL ST", "PROGRAM Main\nVAR p : INT(0..10); x : INT; END_VAR\nLD x\nADD 6\nST x\nST p\nEND_PROGRAM", 5, "Main:6", 2, "x=12; p=6");
    row("IL ST after a deferred operation", "PROGRAM Main\nVAR p : INT(0..10); x : INT := 1; END_VAR\nLD 2\nMUL (x\nADD 4\n)\nST p\nLD x\nADD 1\nST x\nEND_PROGRAM", 5, "Main:7", 2, "p=10; x=2");
    row("struct member", pct + "TYPE S : STRUCT a : Pct; b : INT; END_STRUCT; END_TYPE\nPROGRAM Main\nVAR s : S; x : INT; END_VAR\nx := x + 60;\ns.a := x;\nEND_PROGRAM",
        5, "Main:6", 2, "s.a=60");
    row("array element, index known at run time", pct + "PROGRAM Main\nVAR a : ARRAY[1..3] OF Pct; x : INT; k : INT := 2; END_VAR\nx := x + 60;\na[k] := x;\nEND_PROGRAM",
        5, "Main:5", 2, "a[2]=60");
    row("member of an array element", pct + "TYPE S : STRUCT a : Pct; END_STRUCT; END_TYPE\nPROGRAM Main\nVAR a : ARRAY[0..1] OF S; x : INT; k : INT := 1; END_VAR\nx := x + 60;\na[k].a := x;\nEND_PROGRAM",
        5, "Main:6", 2, "a[1].a=60");
    row("element of a two-dimensional array", "PROGRAM Main\nVAR m : ARRAY[0..1, 0..1] OF SINT(-5..5); x : SINT; END_VAR\nx := x - 3;\nm[1, 0] := x;\nEND_PROGRAM",
        5, "Main:4", 2, "m[1,0]=-3");
    row("bit of a subrange variable", "PROGRAM Main\nVAR p : INT(0..10); n : INT; END_VAR\nn := n + 1;\np.1 := TRUE;\nIF n = 2 THEN p.5 := TRUE; END_IF;\nEND_PROGRAM",
        5, "Main:5", 2, "p=2");
    row("unsigned subrange below its low end", "PROGRAM Main\nVAR u : UINT(10..20); END_VAR\nu := u - 1;\nEND_PROGRAM", 5, "Main:3", 1, "u=10");
    row("global of a subrange type written through VAR_EXTERNAL", "VAR_GLOBAL g : INT(0..10); END_VAR\nPROGRAM Main\nVAR_EXTERNAL g : INT(0..10); END_VAR\nVAR n : INT; END_VAR\nn := n + 4;\ng := n;\nEND_PROGRAM",
        5, "Main:6", 3, "g=8");
    row("input of an FB nested in an FB", pct + "FUNCTION_BLOCK Inner\nVAR_INPUT p : Pct; END_VAR\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK Outer\nVAR_INPUT x : INT; END_VAR\nVAR sub : Inner; END_VAR\nsub(p := x + 1);\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR o : Outer; k : INT := 90; END_VAR\nk := k + 5;\no(x := k);\nEND_PROGRAM", 5, "Outer:8", 2, "o.sub.p=96");
}

void TestSubrange::faults()
{
    QFETCH(QString, source);
    QFETCH(int, cycles);
    QFETCH(QString, fault);
    QFETCH(QString, checks);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    runtime.runCycles(cycles);
    QVERIFY(runtime.fault().has_value());
    QCOMPARE(runtime.fault()->toString(), fault);
    for (const QString &check : checks.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const QString name = check.section(QLatin1Char('='), 0, 0).trimmed();
        QCOMPARE(name + QLatin1Char('=') + runtime.read(qualified(runtime, name)).value_or(QStringLiteral("?")), check.trimmed());
    }
}

// The same ways with values inside the range: no fault, exact values per cycle.
void TestSubrange::valuesInRangePass_data()
{
    table::columns();
    const QByteArray pct(kPct);
    using table::row;
    row("FB input at both ends", pct + "FUNCTION_BLOCK Fb\nVAR_INPUT p : Pct; END_VAR\nVAR_OUTPUT o : INT; END_VAR\no := p;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR x : INT; fb : Fb; END_VAR\nfb(p := x);\nEND_PROGRAM", {"x=0 => fb.o=0", "x=100 => fb.o=100", "x=55 => fb.o=55"});
    row("FOR counter that stops inside its subrange", "PROGRAM Main\nVAR i : INT(0..10); n : INT; END_VAR\nn := 0;\nFOR i := 0 TO 9 DO n := n + 1; END_FOR;\nEND_PROGRAM",
        {"=> i=10; n=10", "=> i=10; n=10"});
    row("FOR counter left with EXIT", "PROGRAM Main\nVAR i : INT(0..10); n : INT; END_VAR\nn := 0;\nFOR i := 0 TO 10 DO\n  n := n + 1;\n  IF i = 10 THEN EXIT; END_IF;\nEND_FOR;\nEND_PROGRAM",
        {"=> i=10; n=11"});
    row("FOR counter with a step known at run time", "PROGRAM Main\nVAR i : INT(0..10); n : INT; s : INT := 3; END_VAR\nn := 0;\nFOR i := 1 TO 7 BY s DO n := n + i; END_FOR;\nEND_PROGRAM",
        {"=> i=10; n=12"});
    row("VAR_IN_OUT round trip", pct + "FUNCTION Bump : BOOL\nVAR_IN_OUT v : INT; END_VAR\nv := v + 30;\nBump := TRUE;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR q : Pct; b : BOOL; END_VAR\nIF q < 90 THEN b := Bump(q); END_IF;\nEND_PROGRAM", {"=> q=30", "=> q=60", "=> q=90", "=> q=90"});
    row("initial values inside the range", pct + "TYPE S : STRUCT a : Pct := 7; END_STRUCT; Low : INT(5..9); END_TYPE\n"
        "PROGRAM Main\nVAR p : Pct := 100; s : S; t : S := (a := 9); arr : ARRAY[1..3] OF Low := [5, 9]; l : Low; END_VAR\nEND_PROGRAM",
        {"=> p=100; s.a=7; t.a=9; arr[1]=5; arr[2]=9; arr[3]=5; l=5"});
    row("function result that is never assigned starts at the low end", "FUNCTION F : INT(5..9)\nVAR_INPUT x : BOOL; END_VAR\nIF x THEN F := 9; END_IF;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR a : INT; b : INT; END_VAR\na := F(FALSE);\nb := F(TRUE);\nEND_PROGRAM", {"=> a=5; b=9"});
    row("bit written inside the range", "PROGRAM Main\nVAR p : INT(0..10); END_VAR\np.3 := TRUE;\np.1 := TRUE;\nEND_PROGRAM", {"=> p=10"});
    row("IL S and R on a BOOL beside a subrange", "PROGRAM Main\nVAR p : INT(0..10); b : BOOL; END_VAR\nLD p\nLT 3\nS b\nLD p\nADD 1\nST p\nGE 3\nR b\nEND_PROGRAM",
        {"=> p=1; b=TRUE", "=> p=2; b=TRUE", "=> p=3; b=FALSE"});
}

void TestSubrange::valuesInRangePass()
{
    table::check();
}

// Constants out of range, and values that cannot reach a subrange variable through VAR_IN_OUT.
void TestSubrange::compileErrors_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("messages");
    const QByteArray pct(kPct);
    const auto row = [](const char *name, const QByteArray &source, const char *messages) {
        QTest::newRow(name) << QString::fromUtf8(source) << QString::fromUtf8(messages);
    };
    const QByteArray fbIn = pct + "FUNCTION_BLOCK Fb\nVAR_INPUT p : Pct; END_VAR\nEND_FUNCTION_BLOCK\n";
    row("constant FB input", fbIn + "PROGRAM Main\nVAR fb : Fb; END_VAR\nfb(p := 101);\nEND_PROGRAM",
        "Main:7:9: error: The value 101 is outside the range 0..100 of Pct.");
    row("constant positional function argument", pct + "FUNCTION Fn : INT\nVAR_INPUT p : Pct; END_VAR\nFn := p;\nEND_FUNCTION\nPROGRAM Main\nVAR y : INT; END_VAR\ny := Fn(-1);\nEND_PROGRAM",
        "Main:8:9: error: The value -1 is outside the range 0..100 of Pct.");
    row("constant function result", pct + "FUNCTION Fn : Pct\nFn := 150;\nEND_FUNCTION\nPROGRAM Main\nVAR y : INT; END_VAR\ny := Fn();\nEND_PROGRAM",
        "Fn:3:1: error: The value 150 is outside the range 0..100 of Pct.");
    row("constant in IL", "PROGRAM Main\nVAR p : INT(0..10); END_VAR\nLD 11\nST p\nEND_PROGRAM",
        "Main:4:1: error: The value 11 is outside the range 0..10 of INT.");
    row("constant FOR start", "PROGRAM Main\nVAR i : INT(1..10); END_VAR\nFOR i := 0 TO 5 DO\nEND_FOR;\nEND_PROGRAM",
        "Main:3:10: error: The value 0 is outside the range 1..10 of INT.");
    row("initial value", pct + "PROGRAM Main\nVAR p : Pct := 101; END_VAR\nEND_PROGRAM",
        "Main:3:16: error: The value 101 is outside the range 0..100 of Pct.");
    row("initial value of an inline subrange", "PROGRAM Main\nVAR p : INT(0..10) := 11; END_VAR\nEND_PROGRAM",
        "Main:2:23: error: The value 11 is outside the range 0..10 of INT.");
    row("default of the type, reported once", "TYPE Pct : INT (0..100) := 200; END_TYPE\nPROGRAM Main\nVAR p : Pct; q : Pct; END_VAR\nEND_PROGRAM",
        "1:28: error: The value 200 is outside the range 0..100 of Pct.");
    row("array initial values", "PROGRAM Main\nVAR a : ARRAY[1..3] OF INT(1..5) := [1, 7, 2]; END_VAR\nEND_PROGRAM",
        "Main:2:41: error: The value 7 is outside the range 1..5 of INT.");
    row("struct initial value", pct + "TYPE S : STRUCT a : Pct; END_STRUCT; END_TYPE\nPROGRAM Main\nVAR s : S := (a := 300); END_VAR\nEND_PROGRAM",
        "Main:4:20: error: The value 300 is outside the range 0..100 of Pct.");
    row("struct member default, reported with the type", pct + "TYPE S : STRUCT a : Pct := 101; END_STRUCT; END_TYPE\nPROGRAM Main\nVAR s : S; END_VAR\nEND_PROGRAM",
        "2:28: error: The value 101 is outside the range 0..100 of Pct.");
    row("FB input default, reported with the FB", "FUNCTION_BLOCK Fb\nVAR_INPUT lim : INT(1..9) := 0; END_VAR\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR a : Fb; b : Fb; END_VAR\nEND_PROGRAM",
        "Fb:2:30: error: The value 0 is outside the range 1..9 of INT.");
    // VAR_IN_OUT passes the variable itself: no conversion, and arrays must match exactly.
    row("VAR_IN_OUT of another type", "FUNCTION Fn : BOOL\nVAR_IN_OUT v : INT; END_VAR\nFn := TRUE;\nEND_FUNCTION\nPROGRAM Main\nVAR r : REAL; b : BOOL; END_VAR\nb := Fn(r);\nEND_PROGRAM",
        "Main:7:9: error: VAR_IN_OUT v of Fn needs a variable of type INT, not REAL. (hint: VAR_IN_OUT passes the variable itself, so no conversion is possible; use a variable of type INT)");
    row("VAR_IN_OUT of a wider integer", "FUNCTION_BLOCK Fb\nVAR_IN_OUT v : DINT; END_VAR\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR i : INT; fb : Fb; END_VAR\nfb(v := i);\nEND_PROGRAM",
        "Main:6:9: error: VAR_IN_OUT v of Fb needs a variable of type DINT, not INT. (hint: VAR_IN_OUT passes the variable itself, so no conversion is possible; use a variable of type DINT)");
    row("VAR_IN_OUT array of another size", "TYPE A5 : ARRAY[1..5] OF INT; A10 : ARRAY[1..10] OF INT; END_TYPE\nFUNCTION Fn : BOOL\nVAR_IN_OUT v : A10; END_VAR\nv[10] := 1;\nFn := TRUE;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR a : A5; b : BOOL; END_VAR\nb := Fn(a);\nEND_PROGRAM",
        "Main:9:9: error: VAR_IN_OUT v of Fn needs a variable of type A10, not A5. (hint: VAR_IN_OUT passes the variable itself, so no conversion is possible; use a variable of type A10)");
    row("VAR_IN_OUT array of subrange elements", pct + "TYPE AP : ARRAY[1..2] OF Pct; AI : ARRAY[1..2] OF INT; END_TYPE\nFUNCTION Fn : BOOL\nVAR_IN_OUT v : AP; END_VAR\nFn := TRUE;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR a : AI; b : BOOL; END_VAR\nb := Fn(a);\nEND_PROGRAM",
        "Main:9:9: error: VAR_IN_OUT v of Fn needs a variable of type AP, not AI. (hint: VAR_IN_OUT passes the variable itself, so no conversion is possible; use a variable of type AP)");
    row("global of a subrange type used from VAR_EXTERNAL", "VAR_GLOBAL g : INT(0..10); END_VAR\nPROGRAM Main\nVAR_EXTERNAL g : INT(0..10); END_VAR\nVAR n : INT; END_VAR\ng := 11;\nEND_PROGRAM",
        "Main:5:1: error: The value 11 is outside the range 0..10 of INT.");
    row("VAR_IN_OUT given an output of another block", "FUNCTION_BLOCK Fb\nVAR_IN_OUT v : BOOL; END_VAR\nv := TRUE;\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR t : TON; fb : Fb; END_VAR\nfb(v := t.Q);\nEND_PROGRAM",
        "Main:7:9: error: t.Q is an output of the function block and can only be read. (hint: VAR_IN_OUT v of Fb may change the variable it is given)");
    row("VAR_IN_OUT given an unknown name, one message", "FUNCTION Fn : BOOL\nVAR_IN_OUT v : INT; END_VAR\nFn := TRUE;\nEND_FUNCTION\nPROGRAM Main\nVAR b : BOOL; END_VAR\nb := Fn(v := nope);\nEND_PROGRAM",
        "Main:7:14: error: Unknown variable 'nope'. (hint: declare it in a VAR section)");
    row("VAR_IN_OUT given an expression", "FUNCTION Fn : BOOL\nVAR_IN_OUT v : INT; END_VAR\nFn := TRUE;\nEND_FUNCTION\nPROGRAM Main\nVAR b : BOOL; i : INT; END_VAR\nb := Fn(v := i + 1);\nEND_PROGRAM",
        "Main:7:16: error: VAR_IN_OUT v of Fn needs a variable, not a value. (hint: it may change what it is given; pass a variable)");
    // was: accepted; the block then wrote through whatever address its slot held (0 at first)
    row("FB called without its VAR_IN_OUT", "FUNCTION_BLOCK Fb\nVAR_IN_OUT v : INT; END_VAR\nv := v + 1;\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR f : Fb; x : INT; END_VAR\nf();\nEND_PROGRAM",
        "Main:7:1: error: f needs a variable for its VAR_IN_OUT v. (hint: pass it in every call, e.g. f(v := variable))");
    row("VAR_IN_OUT given a bit", "FUNCTION Fn : BOOL\nVAR_IN_OUT v : BOOL; END_VAR\nFn := TRUE;\nEND_FUNCTION\nPROGRAM Main\nVAR b : BOOL; w : WORD; END_VAR\nb := Fn(w.1);\nEND_PROGRAM",
        "Main:7:9: error: VAR_IN_OUT v of Fn needs a variable, not a value. (hint: it may change what it is given; pass a variable)");
}

void TestSubrange::compileErrors()
{
    QFETCH(QString, source);
    QFETCH(QString, messages);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QCOMPARE(diagnosticsText(diagnostics, false), messages);
    QVERIFY(!module);
}

// A FOR loop whose counter cannot pass a constant end value compiles with a warning.
void TestSubrange::forLoopWarnings_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("messages");
    const auto row = [](const char *name, const char *declarations, const char *loop, const char *messages) {
        QTest::newRow(name) << QStringLiteral("PROGRAM Main\nVAR %1 END_VAR\n%2\nEND_PROGRAM").arg(QLatin1String(declarations), QLatin1String(loop))
                            << QString::fromUtf8(messages);
    };
    row("subrange counter up to its end", "i : INT(0..10); n : INT;", "FOR i := 0 TO 10 DO n := n + 1; END_FOR;",
        "Main:3:1: warning: This FOR loop ends by setting i to 11, outside its range 0..10, which stops the program. "
        "(hint: give i a type with room for the value that ends the loop)");
    row("subrange counter stepping past its end", "i : INT(0..10); n : INT;", "FOR i := 0 TO 9 BY 3 DO n := n + 1; END_FOR;",
        "Main:3:1: warning: This FOR loop ends by setting i to 12, outside its range 0..10, which stops the program. "
        "(hint: give i a type with room for the value that ends the loop)");
    row("subrange counter downwards", "i : INT(1..10); n : INT; k : INT;", "FOR i := k TO 1 BY -1 DO n := n + 1; END_FOR;",
        "Main:3:1: warning: This FOR loop ends by setting i to 0, outside its range 1..10, which stops the program. "
        "(hint: give i a type with room for the value that ends the loop)");
    row("subrange counter from an unknown start", "i : INT(0..10); n : INT; k : INT;", "FOR i := k TO 9 BY 2 DO n := n + 1; END_FOR;", "");
    row("subrange counter from an unknown start up to its end", "i : INT(0..10); n : INT; k : INT;", "FOR i := k TO 10 BY 3 DO n := n + 1; END_FOR;",
        "Main:3:1: warning: This FOR loop ends by setting i beyond 10, outside its range 0..10, which stops the program. "
        "(hint: give i a type with room for the value that ends the loop)");
    row("subrange counter with room", "i : INT(0..10); n : INT;", "FOR i := 0 TO 9 BY 2 DO n := n + 1; END_FOR;", "");
    row("SINT counter up to 127 wraps around", "i : SINT; n : INT;", "FOR i := 0 TO 127 DO n := n + 1; END_FOR;",
        "Main:3:1: warning: This FOR loop never ends: i wraps around before it can pass 127. (hint: use a larger type than SINT for i)");
    row("USINT counter stepping past 255", "i : USINT; n : INT;", "FOR i := 0 TO 250 BY 10 DO n := n + 1; END_FOR;",
        "Main:3:1: warning: This FOR loop never ends: i wraps around before it can pass 250. (hint: use a larger type than USINT for i)");
    row("USINT counter that ends below 255", "i : USINT; n : INT;", "FOR i := 5 TO 250 BY 10 DO n := n + 1; END_FOR;", "");
    row("INT counter down to its lowest value", "i : INT; k : INT; n : INT;", "FOR i := k TO -32768 BY -1 DO n := n + 1; END_FOR;",
        "Main:3:1: warning: This FOR loop never ends: i wraps around before it can pass -32768. (hint: use a larger type than INT for i)");
}

void TestSubrange::forLoopWarnings()
{
    QFETCH(QString, source);
    QFETCH(QString, messages);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QVERIFY(module);
    QCOMPARE(diagnosticsText(diagnostics, false), messages);
}

QTEST_GUILESS_MAIN(TestSubrange)
#include "tst_subrange.moc"
