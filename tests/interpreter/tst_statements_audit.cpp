// Statements, IL and diagnostics audited against issue 4: one row per behaviour, exact values
// per cycle and exact messages (rows for the bugs the audit found are marked "was:").
#include "tracerunner.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;

class TestStatementsAudit : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void statements_data();
    void statements();
    void instructionList_data();
    void instructionList();
    void faults_data();
    void faults();
    void diagnostics_data();
    void diagnostics();
    void warnings_data();
    void warnings();
};

void TestStatementsAudit::statements_data()
{
    table::columns();
    using table::row;
    row("IF, ELSIF, ELSE",
        "VAR n : INT; r : INT; END_VAR\nn := n + 1;\nIF n = 1 THEN r := 1; ELSIF n = 2 THEN r := 2; ELSIF n = 3 THEN r := 3; ELSE r := 4; END_IF;",
        {"=> r=1", "=> r=2", "=> r=3", "=> r=4"});
    row("CASE with lists, ranges and ELSE",
        "VAR n : INT; r : INT; END_VAR\nn := n + 1;\nCASE n OF\n1, 2: r := 10;\n3..4: r := 20;\n5, 7..8: r := 30;\nELSE r := 99;\nEND_CASE;",
        {"=> r=10", "=> r=10", "=> r=20", "=> r=20", "=> r=30", "=> r=99", "=> r=30", "=> r=30", "=> r=99"});
    row("FOR with a negative step",
        "VAR i : INT; c : INT; END_VAR\nc := 0;\nFOR i := 10 TO 1 BY -3 DO c := c + i; END_FOR;", {"=> c=22; i=-2"});
    row("FOR with a step in a variable",
        "VAR i : INT; c : INT; s : INT := 2; END_VAR\nc := 0;\nFOR i := 1 TO 10 BY s DO c := c + i; END_FOR;", {"=> c=25; i=11", "s=-1 => c=0; i=1", "s=3 => c=22; i=13"});
    row("FOR that does not start keeps the start value",
        "VAR i : INT; c : INT; END_VAR\nFOR i := 1 TO 0 DO c := 99; END_FOR;", {"=> c=0; i=1"});
    row("EXIT leaves the innermost loop only",
        "VAR i : INT; j : INT; e : INT; END_VAR\ne := 0;\nFOR i := 1 TO 5 DO\n  FOR j := 1 TO 5 DO\n    IF j = 3 THEN EXIT; END_IF;\n    e := e + 1;\n  END_FOR;\n"
        "  IF i = 4 THEN EXIT; END_IF;\nEND_FOR;",
        {"=> e=8; i=4; j=3"});
    row("EXIT inside WHILE and REPEAT",
        "VAR w : INT; r : INT; END_VAR\nw := 0; r := 0;\nWHILE TRUE DO w := w + 1; IF w = 4 THEN EXIT; END_IF; END_WHILE;\nREPEAT r := r + 1; IF r = 2 THEN EXIT; END_IF; UNTIL FALSE END_REPEAT;",
        {"=> w=4; r=2"});
    row("WHILE and REPEAT",
        "VAR w : INT; r : INT; END_VAR\nw := 0; r := 0;\nWHILE w < 7 DO w := w + 2; END_WHILE;\nREPEAT r := r + 5; UNTIL r > 12 END_REPEAT;", {"=> w=8; r=15"});
    row("REPEAT runs its body once even when the condition holds",
        "VAR r : INT; END_VAR\nREPEAT r := r + 1; UNTIL TRUE END_REPEAT;", {"=> r=1", "=> r=2"});
    row("RETURN in a function, an FB and a program",
        "FUNCTION Sign : INT\nVAR_INPUT x : INT; END_VAR\nSign := 0;\nIF x > 0 THEN Sign := 1; RETURN; END_IF;\nIF x < 0 THEN Sign := -1; RETURN; END_IF;\nSign := 5;\nEND_FUNCTION\n"
        "FUNCTION_BLOCK Acc\nVAR_INPUT add : INT; END_VAR\nVAR_OUTPUT total : INT; calls : INT; END_VAR\ncalls := calls + 1;\nIF add = 0 THEN RETURN; END_IF;\ntotal := total + add;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR a : INT; b : INT; c : INT; acc : Acc; n : INT; after : INT; END_VAR\n"
        "a := Sign(5); b := Sign(x := -7); c := Sign(0);\nacc(add := n);\nn := n + 1;\nIF n > 2 THEN RETURN; END_IF;\nafter := n;\nEND_PROGRAM",
        {"=> a=1; b=-1; c=5; acc.calls=1; acc.total=0; after=1", "=> acc.total=1; after=2", "=> acc.calls=3; acc.total=3; after=2"});
    row("outputs with =>, positional and formal FB calls",
        "FUNCTION_BLOCK Acc\nVAR_INPUT add : INT; scale : INT := 1; END_VAR\nVAR_OUTPUT total : INT; END_VAR\ntotal := total + add * scale;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR acc : Acc; t : INT; u : INT; END_VAR\nacc(add := 3, total => t);\nacc(2, 10);\nacc(scale := 1, add := 1, total => u);\nEND_PROGRAM",
        {"=> t=3; u=24", "=> t=27; u=48"});
    row("arrays of instances, NOT on an output, defaults of function inputs, RETURN in a loop",
        "FUNCTION_BLOCK Cnt\nVAR_INPUT up : BOOL; step : INT := 1; END_VAR\nVAR_OUTPUT cv : INT; big : BOOL; END_VAR\nIF up THEN cv := cv + step; END_IF;\nbig := cv > 3;\nEND_FUNCTION_BLOCK\n"
        "FUNCTION FirstOver : INT\nVAR_INPUT limit : INT; END_VAR\nVAR i : INT; END_VAR\nFirstOver := -1;\nFOR i := 1 TO 100 DO\n  IF i * i > limit THEN FirstOver := i; RETURN; END_IF;\nEND_FOR;\nEND_FUNCTION\n"
        "FUNCTION Def : INT\nVAR_INPUT a : INT := 7; b : INT := 100; END_VAR\nDef := a + b;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR c : Cnt; nb : BOOL; fbs : ARRAY[1..3] OF Cnt; k : INT := 2; f : INT; d1 : INT; d2 : INT; e : INT; i : INT; END_VAR\n"
        "c(up := TRUE, step := 2, NOT big => nb);\nfbs[k](up := TRUE, step := 5);\nfbs[k + 1](TRUE, 7);\nf := FirstOver(50);\nd1 := Def();\nd2 := Def(b := 1);\n"
        "e := 0;\nFOR i := 1 TO 10 DO\n  CASE i OF\n    3: e := e + 100;\n    5: EXIT;\n  END_CASE;\n  e := e + 1;\nEND_FOR;\nEND_PROGRAM",
        {"=> nb=TRUE; fbs[2].cv=5; fbs[3].cv=7; f=8; d1=107; d2=8; e=104", "=> nb=FALSE; fbs[2].cv=10; fbs[3].cv=14"});
    // was: "Node contains an instance of itself, which would never end."
    row("VAR_IN_OUT of the block's own type",
        "FUNCTION_BLOCK Node\nVAR_INPUT v : INT; END_VAR\nVAR_IN_OUT peer : Node; END_VAR\nVAR_OUTPUT sum : INT; END_VAR\nsum := v + peer.v;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR a : Node; b : Node; s : INT; END_VAR\nb(v := 5, peer := a);\na(v := 2, peer := b);\nb(v := 5, peer := a);\ns := b.sum;\nEND_PROGRAM",
        {"=> s=7; a.sum=7"});
    row("nested FB members: Inst.Sub.Out",
        "FUNCTION_BLOCK Inner\nVAR_INPUT in : INT; END_VAR\nVAR_OUTPUT out : INT; END_VAR\nout := in * 2;\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK Outer\nVAR_INPUT in : INT; END_VAR\nVAR_OUTPUT out : INT; END_VAR\nVAR Sub : Inner; END_VAR\nSub(in := in + 1);\nout := Sub.out;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR Inst : Outer; a : INT; b : INT; END_VAR\nInst(in := 4, out => a);\nb := Inst.Sub.out + Inst.Sub.in;\nEND_PROGRAM",
        {"=> a=10; b=15; Inst.Sub.out=10"});
    row("bit access, read and write",
        "VAR w : WORD := 16#0F; b3 : BOOL; b4 : BOOL; d : DINT; END_VAR\nb3 := w.3;\nb4 := w.4;\nw.3 := FALSE;\nw.8 := TRUE;\nd.31 := TRUE;",
        {"=> b3=TRUE; b4=FALSE; w=263; d=-2147483648"});
    // was: the element's address was folded into the load and the bit was stored at a stale address
    row("bit of an array element with an index in a variable",
        "VAR w : ARRAY[0..3] OF WORD; i : INT := 2; END_VAR\nw[i].3 := TRUE;\nw[i + 1].0 := TRUE;", {"=> w[2]=8; w[3]=1; w[0]=0; w[1]=0"});
    row("string element of an array with an index in a variable",
        "VAR s : ARRAY[0..2] OF STRING[5]; i : INT := 2; END_VAR\ns[i] := CONCAT(s[i], 'ab');", {"=> s[2]='ab'", "=> s[2]='abab'"});
    row("two-dimensional array",
        "VAR m : ARRAY[1..2, 0..2] OF INT; i : INT := 1; j : INT := 2; s : INT; END_VAR\nm[i, j] := 7;\nm[2, 0] := 5;\ns := m[1, 2] + m[i + 1, j - 2];",
        {"=> s=12; m[1,2]=7; m[2,0]=5"});
}

void TestStatementsAudit::statements()
{
    table::check();
}

void TestStatementsAudit::instructionList_data()
{
    table::columns();
    using table::row;
    // Seed 002: LD 5, MUL (6, ADD 7, ), ST ERG gives 65.
    row("deferred operation with brackets", "VAR ERG : INT; END_VAR\nLD 5\nMUL (6\nADD 7\n)\nST ERG", {"=> ERG=65"});
    row("nested brackets", "VAR d : INT; END_VAR\nLD 2\nADD (3\nMUL (4\nSUB 1\n)\n)\nST d", {"=> d=11"});
    row("bracket opened without an operand", "VAR d : INT; x : INT := 4; END_VAR\nLD 10\nSUB (\nLD x\nMUL 2\n)\nST d", {"=> d=2"});
    row("AND, OR, XOR with N and brackets",
        "VAR x : BOOL := TRUE; y : BOOL; z : BOOL; a : BOOL; o : BOOL; e : BOOL; p : BOOL; END_VAR\n"
        "LD x\nANDN y\nST a\nLD y\nOR (x\nAND z\n)\nST o\nLD x\nXORN y\nST e\nLD x\nAND (y\nOR x\n)\nST p",
        {"=> a=TRUE; o=FALSE; e=FALSE; p=TRUE"});
    // was: the N was applied to the first operand inside the brackets, not to their result
    row("ANDN, ORN, XORN with brackets negate the bracket's result",
        "VAR x : BOOL := TRUE; y : BOOL; z : BOOL := TRUE; a : BOOL; o : BOOL; e : BOOL; END_VAR\n"
        "LD x\nANDN (y\nOR z\n)\nST a\nLD FALSE\nORN (z\nAND y\n)\nST o\nLD x\nXORN (y\nOR z\n)\nST e",
        {"=> a=FALSE; o=TRUE; e=TRUE"});
    row("LDN, STN, S, R", "VAR x : BOOL := TRUE; y : BOOL; n : BOOL; s : BOOL; r : BOOL := TRUE; END_VAR\nLDN y\nSTN n\nLD x\nS s\nR r",
        {"=> n=FALSE; s=TRUE; r=FALSE"});
    row("S and R do nothing when the result is FALSE", "VAR s : BOOL; r : BOOL := TRUE; END_VAR\nLD FALSE\nS s\nR r", {"=> s=FALSE; r=TRUE"});
    row("JMP, JMPC, JMPCN",
        "VAR j : INT; END_VAR\nLD 0\nST j\nLD TRUE\nJMPC L1\nLD 1\nST j\nL1: LD j\nADD 10\nST j\nLD FALSE\nJMPCN L2\nLD 100\nST j\nL2:\nLD j\nADD 1\nST j\nJMP L3\nLD 500\nST j\nL3:",
        {"=> j=11"});
    row("CAL, CALC, CALCN with formal arguments",
        "FUNCTION_BLOCK Cnt\nVAR_INPUT up : BOOL; step : INT; END_VAR\nVAR_OUTPUT cv : INT; END_VAR\nIF up THEN cv := cv + step; END_IF;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR c : Cnt; d : Cnt; e : Cnt; END_VAR\nCAL c(up := TRUE, step := 3)\nLD FALSE\nCALC d(up := TRUE, step := 100)\nLD TRUE\nCALCN e(up := TRUE, step := 100)\n"
        "LD TRUE\nCALC d(up := TRUE, step := 1)\nLD FALSE\nCALCN e(up := TRUE, step := 2)\nEND_PROGRAM",
        {"=> c.cv=3; d.cv=1; e.cv=2", "=> c.cv=6; d.cv=2; e.cv=4"});
    row("FB members as operands: T1.Q and T1.ET",
        "VAR T1 : TON; q : BOOL; et : TIME; END_VAR\nCAL T1(IN := TRUE, PT := T#20ms)\nLD T1.Q\nST q\nLD T1.ET\nST et",
        {"=> q=FALSE; et=T#0s", "=> q=FALSE; et=T#10ms", "=> q=TRUE; et=T#20ms"});
    row("function calls with operands",
        "FUNCTION Twice : INT\nVAR_INPUT a : INT; b : INT; END_VAR\nTwice := 2 * a + b;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR f1 : INT; f2 : INT; m : INT; END_VAR\nLD 3\nTwice 4\nST f1\nLD 1\nTwice 10\nADD 1\nST f2\nLD 7\nLIMIT 0, 5\nST m\nEND_PROGRAM",
        {"=> f1=10; f2=13; m=5"});
    // was: "An IL instruction takes one operand; ':=' is left over"
    row("CAL with outputs, FB inputs set with ST, arrays of instances",
        "FUNCTION_BLOCK Cnt\nVAR_INPUT up : BOOL; step : INT := 1; END_VAR\nVAR_OUTPUT cv : INT; big : BOOL; END_VAR\nIF up THEN cv := cv + step; END_IF;\nbig := cv > 3;\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR c : Cnt; x : INT; nb : BOOL; ic : Cnt; fbs : ARRAY[1..3] OF Cnt; k : INT := 2; r : INT; END_VAR\n"
        "CAL c(up := TRUE, step := 2, cv => x, big => nb)\nLD TRUE\nST ic.up\nCAL ic\nCAL fbs[k](up := TRUE)\nLD fbs[k].cv\nST r\nEND_PROGRAM",
        {"=> x=2; nb=FALSE; ic.cv=1; r=1", "=> x=4; nb=TRUE; ic.cv=2; r=2"});
    row("function calls with a formal argument list, also over several lines",
        "FUNCTION Twice : INT\nVAR_INPUT a : INT; b : INT; END_VAR\nTwice := 2 * a + b;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR f : INT; g : INT; m : INT; x : INT := 9; END_VAR\nLD 100\nTwice(b := 10, a := 1)\nST f\n"
        "Twice(\n  a := 3,\n  b := x\n)\nADD 1\nST g\nLIMIT(\n  MN := 1,\n  IN := x,\n  MX := 5\n)\nST m\nEND_PROGRAM",
        {"=> f=12; g=16; m=5"});
    row("RET, RETC, RETCN",
        "VAR n : INT; a : INT; b : INT; END_VAR\nLD n\nADD 1\nST n\nGT 2\nRETC\nLD n\nST a\nLD n\nLT 2\nRETCN\nLD n\nST b",
        {"=> n=1; a=1; b=1", "=> n=2; a=2; b=1", "=> n=3; a=2; b=1"});
    row("RET ends a function", "FUNCTION F : INT\nVAR_INPUT x : INT; END_VAR\nLD x\nST F\nGT 5\nRETC\nLD 0\nST F\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR a : INT; b : INT; END_VAR\na := F(9);\nb := F(3);\nEND_PROGRAM",
        {"=> a=9; b=0"});
}

void TestStatementsAudit::instructionList()
{
    table::check();
}

void TestStatementsAudit::faults_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<int>("cycles");
    QTest::addColumn<QString>("fault");
    QTest::newRow("two-dimensional index out of range")
        << QStringLiteral("PROGRAM Main\nVAR m : ARRAY[1..2, 0..2] OF INT; i : INT := 1; j : INT; END_VAR\ni := i + 1;\nm[i, j] := 1;\nEND_PROGRAM")
        << 5 << QStringLiteral("Main:4: Array index out of range. (cycle 2)");
    QTest::newRow("second index out of range")
        << QStringLiteral("PROGRAM Main\nVAR m : ARRAY[1..2, 0..2] OF INT; j : INT; x : INT; END_VAR\nj := j + 1;\nx := m[2, j];\nEND_PROGRAM")
        << 5 << QStringLiteral("Main:4: Array index out of range. (cycle 3)");
    QTest::newRow("FOR with a step of 0 at run time never ends")
        << QStringLiteral("PROGRAM Main\nVAR i : INT; s : INT; n : INT; END_VAR\nFOR i := 1 TO 10 BY s DO\n  n := n + 1;\nEND_FOR;\nEND_PROGRAM")
        << 1 << QStringLiteral("Main:3: The program ran too long in one cycle; is there an endless loop? (cycle 1)");
}

void TestStatementsAudit::faults()
{
    QFETCH(QString, source);
    QFETCH(int, cycles);
    QFETCH(QString, fault);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    runtime.vm().budgetPerRun = 100'000;
    runtime.runCycles(cycles);
    QVERIFY(runtime.fault().has_value());
    QCOMPARE(runtime.fault()->toString(), fault);
}

// Wrong programs: exactly the messages expected, every one located, one per mistake.
void TestStatementsAudit::diagnostics_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("messages");
    const auto row = [](const char *name, const char *body, const char *messages) {
        const QString source = QString::fromUtf8(body).contains(QLatin1String("PROGRAM"))
            ? QString::fromUtf8(body)
            : QStringLiteral("PROGRAM Main\nVAR a : INT; b : INT; END_VAR\n%1\nEND_PROGRAM\n").arg(QString::fromUtf8(body));
        QTest::newRow(name) << source << QString::fromUtf8(messages);
    };
    row("'=' where ':=' was meant", "a = 5;\nb := a;", "Main:3:1: error: '=' compares two values; to assign a value write ':='. (hint: write a := ...;)");
    row("two '=' for ':=', two messages", "b = a + 1;\nIF b = 2 THEN a = 3; END_IF;",
        "Main:3:1: error: '=' compares two values; to assign a value write ':='. (hint: write b := ...;) | "
        "Main:4:15: error: '=' compares two values; to assign a value write ':='. (hint: write a := ...;)");
    row("':=' in a condition", "IF a := 1 THEN b := 2; END_IF;", "Main:3:6: error: A condition compares with '=', not ':='.");
    // was: "Expected a value ... found '='" without a hint
    row("'==' for '='", "IF a == 1 THEN b := 1; END_IF;",
        "Main:3:7: error: Expected a value, a variable or a function call but found '='. (hint: IEC 61131-3 compares with a single '=')");
    row("missing END_IF, reported at its IF", "IF a > 0 THEN\n  b := 1;\nb := 2;",
        "Main:3:1: error: This IF has no matching END_IF. (hint: add END_IF; after the last statement that belongs to it)");
    row("missing END_IF inside a loop, reported at the inner IF", "FOR a := 1 TO 3 DO\n  IF a > 1 THEN\n    b := 1;\nEND_FOR;\nb := 3;",
        "Main:4:3: error: This IF has no matching END_IF. (hint: add END_IF; after the last statement that belongs to it)");
    // was: the same message with the usual hint, which does not explain why END_IF is missing
    row("ELSE IF for ELSIF", "IF a = 1 THEN\n  b := 1;\nELSE IF a = 2 THEN\n  b := 2;\nEND_IF;",
        "Main:3:1: error: This IF has no matching END_IF. (hint: ELSE IF opens a second IF that needs its own END_IF; write ELSIF instead)");
    // was: two messages ("Expected ':=' or a call after 'END_FI'" and "This IF has no matching END_IF")
    row("misspelled END_IF, one message", "IF a > 1 THEN b := 1; END_FI;\nb := 2;",
        "Main:3:23: error: Expected END_IF but found 'END_FI'. (hint: the IF of line 3 ends with END_IF)");
    row("misspelled END_WHILE inside a WHILE", "WHILE a < 3 DO\n  IF a = 1 THEN a := 5; END_IF;\n  a := a + 1;\nEND_WHIL;\nb := 1;",
        "Main:6:1: error: Expected END_WHILE but found 'END_WHIL'. (hint: the WHILE of line 3 ends with END_WHILE)");
    // was: two messages, the second at the END_IF of the misspelled IF
    row("misspelled IF, one message", "IFF a > 1 THEN b := 1; END_IF;\nb := 2;",
        "Main:3:5: error: Expected ':=' or a call after 'IFF'. (hint: did you mean IF?)");
    row("misspelled WHILE, one message", "WHILEE a < 3 DO\n  a := a + 1;\nEND_WHILE;\nb := 1;",
        "Main:3:8: error: Expected ':=' or a call after 'WHILEE'. (hint: did you mean WHILE?)");
    // was: "Expected a statement but found '2'"
    row("case label without ':'", "CASE a OF\n1: b := 1;\n2 b := 2;\nEND_CASE;\nb := 3;", "Main:5:3: error: Expected ':' after the case label but found 'b'.");
    row("missing ';', one message per statement", "a := b + 2\nb := a;\nIF a > 2 THEN b := 1 END_IF;",
        "Main:3:11: error: Missing ';' at the end of the statement. (hint: every ST statement ends with ';') | "
        "Main:5:21: error: Missing ';' at the end of the statement. (hint: every ST statement ends with ';')");
    // was: the second line was skipped while recovering from the first
    row("two broken lines, two messages", "b := a +;\nb := 2 +;",
        "Main:3:9: error: Expected a value, a variable or a function call but found ';'. | Main:4:9: error: Expected a value, a variable or a function call but found ';'.");
    // was: "Missing ';' at the end of the statement." at the ')'
    row("')' without '('", "b := a + 1);\nb := 2;", "Main:3:11: error: This ')' has no matching '('.");
    // was: "''abc;' is not valid IEC 61131-3 text."
    row("string not closed", "b := 'abc;\nb := 1;",
        "Main:3:6: error: This string is not closed on its line. (hint: close the string on the same line, and write $$ for a dollar sign)");
    row("missing THEN", "IF a > 1 b := 1; END_IF;\nb := 2;", "Main:3:10: error: Expected THEN but found 'b'.");
    row("missing DO", "WHILE a < 5\n a := a + 1;\nEND_WHILE;", "Main:4:2: error: Expected DO but found 'a'.");
    row("FOR with '='", "FOR a = 1 TO 10 DO b := 1; END_FOR;", "Main:3:7: error: Expected ':=' and the start value but found '='.");
    row("FOR with a constant step of 0", "FOR a := 1 TO 10 BY 0 DO b := 1; END_FOR;", "Main:3:21: error: A FOR loop with step 0 never ends.");
    row("one unknown name, one message", "a := nope + 1;\nb := a;", "Main:3:6: error: Unknown variable 'nope'. (hint: declare it in a VAR section)");
    // was: "Expected ':=' or a call after 'END_PROGRAMM'" and the POU's end missing
    row("misspelled END_PROGRAM", "PROGRAM Main\nVAR a : INT; END_VAR\na := 1;\nEND_PROGRAMM\nPROGRAM B\nVAR x : INT; END_VAR\nx := 1;\nEND_PROGRAM\n",
        "Main:4:1: error: Expected END_PROGRAM but found 'END_PROGRAMM'.");
    // was: one more "Unknown variable" (or "Unknown function") at every use of the variable
    row("unknown type, one message", "PROGRAM Main\nVAR a : INTT; b : INT; t : TONN; END_VAR\na := 1;\nb := a + 2;\nIF a > 1 THEN b := 0; END_IF;\n"
        "t(IN := TRUE, PT := T#1s);\nb := BOOL_TO_INT(t.Q);\nEND_PROGRAM",
        "Main:2:9: error: Unknown type 'INTT'. | Main:2:28: error: Unknown type 'TONN'.");
    row("unknown type of a global, one message", "VAR_GLOBAL g : Motor; END_VAR\nPROGRAM Main\nVAR b : INT; END_VAR\ng := 1;\nb := g;\nEND_PROGRAM",
        "1:16: error: Unknown type 'Motor'.");
    // was: accepted, the 2 silently went to the first input
    row("formal and positional arguments mixed", "FUNCTION_BLOCK Fb\nVAR_INPUT x : INT; y : INT; END_VAR\nEND_FUNCTION_BLOCK\nPROGRAM Main\nVAR f : Fb; END_VAR\nf(y := 1, 2);\nEND_PROGRAM",
        "Main:6:1: error: A call gives either all its arguments by name or none; here only some have a name. (hint: write each argument as name := value)");
    row("recursion refused", "FUNCTION F : INT\nVAR_INPUT n : INT; END_VAR\nIF n > 0 THEN F := n + G(n - 1); END_IF;\nEND_FUNCTION\n"
        "FUNCTION G : INT\nVAR_INPUT n : INT; END_VAR\nG := F(n);\nEND_FUNCTION\nPROGRAM Main\nVAR a : INT; END_VAR\na := F(3);\nEND_PROGRAM",
        "G:7:6: error: Recursion is not allowed in IEC 61131-3: F calls itself (F -> G -> F).");
    // was: "Fact is a DINT, not a function block; it cannot be called."
    row("direct recursion of a function", "FUNCTION Fact : DINT\nVAR_INPUT n : DINT; END_VAR\nIF n <= 1 THEN Fact := 1; ELSE Fact := n * Fact(n - 1); END_IF;\nEND_FUNCTION\n"
        "PROGRAM Main\nVAR x : DINT; END_VAR\nx := Fact(5);\nEND_PROGRAM",
        "Fact:3:44: error: Recursion is not allowed in IEC 61131-3: Fact calls itself (Fact -> Fact).");
    row("function block containing itself", "FUNCTION_BLOCK A\nVAR b : B; END_VAR\nb();\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK B\nVAR a : A; END_VAR\na();\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR x : A; END_VAR\nx();\nEND_PROGRAM",
        "A:1:1: error: A contains an instance of itself, which would never end.");
    row("EXIT outside a loop", "EXIT;", "Main:3:1: error: EXIT is only allowed inside a FOR, WHILE or REPEAT loop.");
    // was: one message per ST line, and "Main has no END_PROGRAM" after a stray END_IF
    row("ST inside an IL body, one message", "LD 1\nST a\nIF a = 1 THEN\n  b := 2;\nEND_IF;\nb := 3;",
        "Main:5:1: error: This is ST, but the body is written in IL; a body uses one language. (hint: write it in IL (LD, ST, JMPC ...) or write the whole body in ST)");
    row("ST call inside an IL body", "LD 1\nST a\nnope(x := 1);\nLD 2",
        "Main:5:1: error: This is ST, but the body is written in IL; a body uses one language. (hint: write it in IL (LD, ST, JMPC ...) or write the whole body in ST)");
    row("IL bracket never closed", "LD 1\nADD (2\nST a", "Main:4:1: error: This '(' is never closed with ')'.");
    row("IL jump to a missing label", "LD TRUE\nJMPC Nowhere\nLD 1\nST a", "Main:4:1: error: There is no label Nowhere to jump to.");
}

void TestStatementsAudit::diagnostics()
{
    QFETCH(QString, source);
    QFETCH(QString, messages);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QCOMPARE(diagnosticsText(diagnostics, false), messages);
    QVERIFY(!module);
}

// Programs that run, with a warning about something that is probably not meant.
void TestStatementsAudit::warnings_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("messages");
    QTest::addColumn<QStringList>("steps");
    // was: no message; the second branch silently never ran for 2
    QTest::newRow("overlapping case labels")
        << QStringLiteral("PROGRAM Main\nVAR n : INT; k : INT; END_VAR\nCASE n OF\n1, 2: k := 1;\n2..4: k := 2;\nEND_CASE;\nn := n + 1;\nEND_PROGRAM")
        << QStringLiteral("Main:5:1: warning: The case value 2 is already handled on line 4; only the first branch runs for it.")
        << QStringList{"=> k=0", "=> k=1", "=> k=1", "=> k=2"};
    QTest::newRow("enumeration value twice")
        << QStringLiteral("TYPE Color : (Red, Green, Blue); END_TYPE\nPROGRAM Main\nVAR c : Color := Green; k : INT; END_VAR\n"
                          "CASE c OF\nRed, Green: k := 1;\nBlue, Green: k := 2;\nEND_CASE;\nEND_PROGRAM")
        << QStringLiteral("Main:6:7: warning: The case value Green is already handled on line 5; only the first branch runs for it.")
        << QStringList{"=> k=1"};
    QTest::newRow("distinct case labels") << QStringLiteral("PROGRAM Main\nVAR n : INT; k : INT; END_VAR\nCASE n OF\n-5..-1: k := -1;\n0: k := 0;\n1, 2: k := 1;\nEND_CASE;\nEND_PROGRAM")
                                          << QString() << QStringList{"n=-3 => k=-1", "n=0 => k=0", "n=2 => k=1"};
}

void TestStatementsAudit::warnings()
{
    QFETCH(QString, source);
    QFETCH(QString, messages);
    QFETCH(QStringList, steps);
    Diagnostics diagnostics;
    QVERIFY(compileText(source, diagnostics));
    QCOMPARE(diagnosticsText(diagnostics, false), messages);
    QCOMPARE(runTrace(source, steps), QString());
}

QTEST_GUILESS_MAIN(TestStatementsAudit)
#include "tst_statements_audit.moc"
