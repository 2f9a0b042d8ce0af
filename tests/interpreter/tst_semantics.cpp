// Wrong programs: located, single-cause diagnostics with the messages a student reads.
#include "interpreter/compiler/compiler.h"

#include <QTest>

using namespace iec::interp;

class TestSemantics : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void diagnostics_data();
    void diagnostics();
    void correctProgramHasNoDiagnostics();
    void sfcBodiesCompileWithAWarning();
};

void TestSemantics::diagnostics_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("messages");
    const auto row = [](const char *name, const char *source, const char *messages) {
        QTest::newRow(name) << QString::fromUtf8(source) << QString::fromUtf8(messages);
    };
    row("unknown variable", "PROGRAM Main\nVAR a : INT; END_VAR\nb := a;\nEND_PROGRAM",
        "Main:3:1: error: Unknown variable 'b'. (hint: declare it in a VAR section)");
    // Narrowing and REAL to integer are warnings as in CODESYS (tst_dialect); BOOL and TIME to a
    // number are not converted implicitly there either.
    row("bool to int needs a conversion", "PROGRAM Main\nVAR i : INT; b : BOOL; END_VAR\ni := b;\nEND_PROGRAM",
        "Main:3:1: error: A value of type BOOL cannot be used as INT i without a conversion. (hint: convert it explicitly, e.g. BOOL_TO_INT(...))");
    row("time to int needs a conversion", "PROGRAM Main\nVAR i : DINT; t : TIME; END_VAR\ni := t;\nEND_PROGRAM",
        "Main:3:1: error: A value of type TIME cannot be used as DINT i without a conversion. (hint: convert it explicitly, e.g. TIME_TO_DINT(...))");
    row("literal out of range", "PROGRAM Main\nVAR s : SINT; END_VAR\ns := 200;\nEND_PROGRAM",
        "Main:3:1: error: The value 200 does not fit into SINT (-128 to 127).");
    row("typed literals never wrap", "PROGRAM Main\nVAR i : INT; b : BYTE; END_VAR\ni := INT#40000;\nb := BYTE#-1;\nb := BYTE#255; i := INT#-32768;\nEND_PROGRAM",
        "Main:3:6: error: The value INT#40000 does not fit into INT (-32768 to 32767).\n"
        "Main:4:6: error: The value BYTE#-1 does not fit into BYTE (0 to 255).");
    row("typed 64-bit literals never wrap", "PROGRAM Main\nVAR u : ULINT; l : LINT; END_VAR\nu := ULINT#-1;\nl := LINT#9223372036854775808;\nEND_PROGRAM",
        "Main:3:6: error: The value ULINT#-1 does not fit into ULINT.\n"
        "Main:4:6: error: The value LINT#9223372036854775808 does not fit into LINT.");
    row("initial value out of range", "PROGRAM Main\nVAR b : BYTE := 256; END_VAR\nEND_PROGRAM",
        "Main:2:17: error: The value 256 does not fit into BYTE (0 to 255).");
    row("condition must be bool", "PROGRAM Main\nVAR i : INT; END_VAR\nIF i THEN i := 0; END_IF;\nEND_PROGRAM",
        "Main:3:4: error: A condition must be BOOL, not INT. (hint: compare it, e.g. x <> 0)");
    row("and needs bits or integers", "PROGRAM Main\nVAR r : REAL; b : BOOL; END_VAR\nb := r AND 1;\nEND_PROGRAM",
        "Main:3:8: error: 'AND' needs BOOL or a bit string (BYTE, WORD, ...), not REAL.");
    row("mixing incompatible types", "PROGRAM Main\nVAR t : TIME; i : INT; x : INT; END_VAR\nx := i + t;\nEND_PROGRAM",
        "Main:3:8: error: '+' cannot combine INT and TIME.");
    row("constant cannot change", "PROGRAM Main\nVAR CONSTANT N : INT := 3; END_VAR\nN := 4;\nEND_PROGRAM",
        "Main:3:1: error: N is a constant and cannot be changed.");
    row("fb output is read only", "PROGRAM Main\nVAR t : TON; END_VAR\nt.Q := TRUE;\nEND_PROGRAM",
        "Main:3:1: error: t.Q is an output of the function block and can only be read.");
    row("fb call in an expression", "PROGRAM Main\nVAR t : TON; b : BOOL; END_VAR\nb := t(IN := TRUE);\nEND_PROGRAM",
        "Main:3:6: error: A function block call is a statement of its own. (hint: call t(...); then read its outputs, e.g. t.Q)");
    row("output connected with :=", "PROGRAM Main\nVAR t : TON; b : BOOL; END_VAR\nt(IN := TRUE, Q := b);\nEND_PROGRAM",
        "Main:3:20: error: Q is an output of TON; connect it with '=>'. (hint: write Q => variable)");
    row("unknown function", "PROGRAM Main\nVAR x : INT; END_VAR\nx := Foo(1);\nEND_PROGRAM",
        "Main:3:6: error: Unknown function 'Foo'.");
    row("unknown type", "PROGRAM Main\nVAR x : Motor; END_VAR\nEND_PROGRAM",
        "Main:2:9: error: Unknown type 'Motor'.");
    row("index out of range", "PROGRAM Main\nVAR a : ARRAY[1..10] OF INT; END_VAR\na[11] := 0;\nEND_PROGRAM",
        "Main:3:3: error: The index 11 is outside the range 1..10 of a.");
    row("exit outside a loop", "PROGRAM Main\nVAR x : INT; END_VAR\nEXIT;\nEND_PROGRAM",
        "Main:3:1: error: EXIT is only allowed inside a FOR, WHILE or REPEAT loop.");
    row("recursion", "FUNCTION F : INT\nVAR_INPUT n : INT; END_VAR\nF := G(n);\nEND_FUNCTION\n"
                     "FUNCTION G : INT\nVAR_INPUT n : INT; END_VAR\nG := F(n - 1);\nEND_FUNCTION\n"
                     "PROGRAM Main\nVAR x : INT; END_VAR\nx := F(3);\nEND_PROGRAM",
        "G:7:6: error: Recursion is not allowed in IEC 61131-3: F calls itself (F -> G -> F).");
    row("fb containing itself", "FUNCTION_BLOCK Loop\nVAR inner : Loop; END_VAR\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR l : Loop; END_VAR\nEND_PROGRAM",
        "Loop:1:1: error: Loop contains an instance of itself, which would never end.");
    row("il unknown label", "PROGRAM Main\nVAR x : BOOL; END_VAR\nLD x\nJMPC Nowhere\nEND_PROGRAM",
        "Main:4:1: error: There is no label Nowhere to jump to.");
    row("il needs a current result", "PROGRAM Main\nVAR x : INT; END_VAR\nADD 1\nST x\nEND_PROGRAM",
        "Main:3:1: error: ADD needs a current result; load one first with LD.");
    row("il error does not cascade", "PROGRAM Main\nVAR y : INT; END_VAR\nLD x\nADD 1\nMUL 2\nST y\nEND_PROGRAM",
        "Main:3:4: error: Unknown variable 'x'. (hint: declare it in a VAR section)");
    row("il type error does not cascade", "PROGRAM Main\nVAR y : INT; t : TIME; END_VAR\nLD y\nADD t\nMUL 2\nST y\nEND_PROGRAM",
        "Main:4:1: error: '+' cannot combine INT and TIME.");
    row("array too large", "PROGRAM Main\nVAR a : ARRAY[1..200000000] OF LREAL; END_VAR\nEND_PROGRAM",
        "Main:2:9: error: This array needs 1525 MB; an array may use at most 256 MB.");
    row("string too long", "PROGRAM Main\nVAR s : STRING[3] := 'abcde'; END_VAR\nEND_PROGRAM",
        "Main:2:22: error: The text has 5 characters but s holds only 3.");
    row("wrong argument count", "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\nF := a;\nEND_FUNCTION\nPROGRAM Main\nVAR x : INT; END_VAR\nx := F(1, 2);\nEND_PROGRAM",
        "Main:7:11: error: F takes only 1 argument(s).");
    row("missing in out", "FUNCTION F : INT\nVAR_IN_OUT a : INT; END_VAR\nF := a;\nEND_FUNCTION\nPROGRAM Main\nVAR x : INT; END_VAR\nx := F();\nEND_PROGRAM",
        "Main:7:6: error: F needs a variable for its VAR_IN_OUT a.");
    row("one unknown name, one message per use", "PROGRAM Main\nVAR x : INT; END_VAR\nx := y + 1;\nEND_PROGRAM",
        "Main:3:6: error: Unknown variable 'y'. (hint: declare it in a VAR section)");
    row("missing global, one message", "PROGRAM Main\nVAR_EXTERNAL limit : INT; END_VAR\nVAR x : INT; END_VAR\nx := limit;\nx := limit + 1;\nEND_PROGRAM",
        "Main:2:14: error: There is no global variable limit for this VAR_EXTERNAL. (hint: declare it in VAR_GLOBAL)");
    row("negating unsigned", "PROGRAM Main\nVAR u : UINT; END_VAR\nu := -u;\nEND_PROGRAM",
        "Main:3:6: error: A UINT cannot be negated.");
    row("constant outside a subrange", "TYPE Percent : INT (0..100); END_TYPE\nPROGRAM Main\nVAR p : Percent; END_VAR\np := 101;\nEND_PROGRAM",
        "Main:4:1: error: The value 101 is outside the range 0..100 of Percent.");
    row("action with arguments", "PROGRAM Main\nVAR n : INT; END_VAR\nReset(1);\nACTION Reset:\nn := 0;\nEND_ACTION\nEND_PROGRAM",
        "Main:3:1: error: The action Main.Reset takes no arguments.");
    // A POU's own variable hides the global constant of its name, and has no value while it is laid out.
    row("a variable as an array bound", "VAR_GLOBAL CONSTANT N : INT := 3; END_VAR\nPROGRAM Main\nVAR N : INT := 5; a : ARRAY[0..N] OF INT; END_VAR\na[0] := 1;\nEND_PROGRAM",
        "Main:3:32: error: N is a variable, not a constant: it has no value before the program runs. (hint: declare it in VAR CONSTANT with an initial value)");
    // The author's own {error}: the rest is still checked, and the program does not run.
    row("error pragma", "PROGRAM Main\nVAR x : INT; END_VAR\n{error 'not finished'}\nx := y;\nEND_PROGRAM",
        "Main:3:1: error: not finished\nMain:4:6: error: Unknown variable 'y'. (hint: declare it in a VAR section)");
    row("program selection", "PROGRAM A\nEND_PROGRAM\nPROGRAM B\nEND_PROGRAM\nCONFIGURATION C\nTASK T(INTERVAL := T#10ms);\nPROGRAM P WITH T : Nope;\nEND_CONFIGURATION",
        "C:7:9: error: There is no PROGRAM called Nope.");
}

void TestSemantics::diagnostics()
{
    QFETCH(QString, source);
    QFETCH(QString, messages);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QVERIFY(!module);
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << d.toString();
    QCOMPARE(lines.join(QLatin1Char('\n')), messages);
}

void TestSemantics::correctProgramHasNoDiagnostics()
{
    Diagnostics diagnostics;
    const auto module = compileText(QStringLiteral("PROGRAM Main\nVAR t : TON; c : CTU; x : INT; END_VAR\nt(IN := TRUE, PT := T#1s);\nc(CU := t.Q);\nx := c.CV;\nEND_PROGRAM"), diagnostics);
    QVERIFY(module);
    QCOMPARE(diagnostics.all().size(), size_t{0});
}

void TestSemantics::sfcBodiesCompileWithAWarning()
{
    Diagnostics diagnostics;
    const auto module = compileText(QStringLiteral("PROGRAM Main\nVAR x : BOOL; END_VAR\nINITIAL_STEP S1: END_STEP\nTRANSITION FROM S1 TO S1 := x; END_TRANSITION\nEND_PROGRAM"), diagnostics);
    QVERIFY(module);
    QCOMPARE(diagnostics.all().size(), size_t{1});
    QCOMPARE(diagnostics.all()[0].toString(), QStringLiteral("Main:1:1: warning: Main is a sequential function chart; charts run with the next version of the interpreter."));
}

QTEST_GUILESS_MAIN(TestSemantics)
#include "tst_semantics.moc"
