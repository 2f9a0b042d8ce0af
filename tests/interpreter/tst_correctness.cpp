// Three kinds of wrong results found by running random programs beside another IEC 61131-3
// compiler, each with the values IEC 61131-3 (and CODESYS) give:
//  - a jump in IL does not change the current result (IEC 61131-3 ed.2 table 52: JMP jumps to
//    the label, the current result is untouched; CODESYS: the accumulator is not reloaded);
//  - CASE takes any expression as selector, constants included;
//  - an untyped literal takes the type its use needs, also inside generic functions.
#include "tracerunner.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;
using namespace iec::interp::testing::table;

class TestCorrectness : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void ilJumpKeepsCurrentResult_data();
    void ilJumpKeepsCurrentResult() { check(); }
    void caseWithConstantSelector_data();
    void caseWithConstantSelector() { check(); }
    void literalsTypedByTheirUse_data();
    void literalsTypedByTheirUse() { check(); }
    void foldedLikeAtRunTime_data();
    void foldedLikeAtRunTime() { check(); }
};

void TestCorrectness::ilJumpKeepsCurrentResult_data()
{
    columns();
    // The counter: the jump skips LD 99, so ST stores Cnt + 1 and the counter counts.
    row("jmp carries the sum", "VAR Cnt : INT; END_VAR\n LD Cnt\n ADD 1\n JMP L1\n LD 99\nL1: ST Cnt",
        {"=> Cnt=1", "=> Cnt=2", "=> Cnt=3"});
    row("label on its own line", "VAR Cnt : INT; END_VAR\n LD Cnt\n ADD 1\n JMP L1\n LD 99\nL1:\n ST Cnt",
        {"=> Cnt=1", "=> Cnt=2"});
    // JMPC is taken with the current result TRUE: Big is Cnt > 5 (the LD FALSE is skipped then).
    row("jmpc carries TRUE", "VAR Cnt : INT; Big : BOOL; END_VAR\n LD Cnt\n ADD 1\n ST Cnt\n GT 5\n JMPC L1\n LD FALSE\nL1: ST Big",
        {"=> Cnt=1; Big=FALSE", "Cnt=5 => Cnt=6; Big=TRUE", "Cnt=0 => Cnt=1; Big=FALSE"});
    // JMPCN is taken with FALSE: Out follows Flag.
    row("jmpcn carries FALSE", "VAR Flag : BOOL; Out : BOOL; END_VAR\n LD Flag\n JMPCN L1\n LD TRUE\nL1: ST Out",
        {"=> Out=FALSE", "Flag=TRUE => Out=TRUE", "Flag=FALSE => Out=FALSE"});
    // After the label the current result is not a constant: MUL 1000 runs on Cnt + 1 and wraps
    // like INT (1001 * 1000 = 1001000 = 16#F4628, low 16 bits 16#4628 = 17960).
    row("no folding after a label", "VAR Cnt : INT; END_VAR\n LD Cnt\n ADD 1\n JMP L1\n LD 99\nL1: MUL 1000\n ST Cnt",
        {"=> Cnt=1000", "=> Cnt=17960", "=> Cnt=4136"});
    // A jump back carries its value to the label too: 1 doubled until it reaches 128.
    row("jump back carries the value", "VAR v : INT; r : INT; END_VAR\n LD 1\nLoop: MUL 2\n ST v\n LT 100\n JMPC Back\n JMP Done\n"
                                       "Back: LD v\n JMP Loop\nDone: LD v\n ST r",
        {"=> v=128; r=128"});
    // The seed programs still run as before (labels whose code starts with LD).
    row("jump over a branch", "VAR A : INT := 10; B : INT := 50; C : INT; END_VAR\n"
                              " LD 100\n SUB A\n GE B\n JMPC Next1\n LD A\n ADD B\n ST C\n JMP Next2\nNext1:\n LD A\n SUB B\n ST C\nNext2:",
        {"=> C=-40", "A=60 => C=110"});
}

void TestCorrectness::caseWithConstantSelector_data()
{
    columns();
    expr("literal", "r : INT;", "CASE 2 OF 2: r := 1; ELSE r := 2; END_CASE;", "r=1");
    expr("negative literal", "r : INT;", "CASE -2 OF -2: r := 1; ELSE r := 2; END_CASE;", "r=1");
    expr("constant expression", "r : INT;", "CASE 1 - 3 OF -2: r := 1; ELSE r := 2; END_CASE;", "r=1");
    expr("typed literal", "r : INT;", "CASE INT#-2 OF -2: r := 1; ELSE r := 2; END_CASE;", "r=1");
    expr("no branch matches", "r : INT;", "CASE 7 OF 1, 2: r := 1; 3..5: r := 3; ELSE r := 2; END_CASE;", "r=2");
    expr("range", "r : INT;", "CASE 4 OF 1, 2: r := 1; 3..5: r := 3; ELSE r := 2; END_CASE;", "r=3");
    expr("second label of a branch", "r : INT;", "CASE 2 OF 1, 2: r := 1; ELSE r := 2; END_CASE;", "r=1");
    row("constant variable", "VAR CONSTANT k : INT := 3; END_VAR VAR r : INT; END_VAR\nCASE k OF 1: r := 1; 3: r := 3; END_CASE;", {"=> r=3"});
}

void TestCorrectness::literalsTypedByTheirUse_data()
{
    columns();
    // NOT 16#0159 in a WORD is 16#FEA6 = 65190.
    row("not of a literal with a word", "VAR w : WORD; END_VAR\nw := w OR NOT 16#0159;", {"=> w=65190", "=> w=65190"});
    // 507 * 2^9 = 259584 = 16#3_F600; a WORD keeps 16#F600 = 62976.
    expr("shift of literals into a word", "w : WORD;", "w := SHL(507, 9);", "w=62976");
    // SEL of literals rotated in the destination's width: 8 ROR 3 = 1; 9 ROR 3 in a BYTE is
    // 2#0010_0001 = 33.
    row("rotate a selection of literals", "VAR b : BOOL; w : WORD; y : BYTE; END_VAR\nw := ROR(SEL(b, 0, 16#0008), 3); y := ROR(SEL(b, 0, 16#09), 3);",
        {"=> w=0; y=0", "b=TRUE => w=1; y=33"});
    // The inner MUX of literals takes the SINT of the outer one: i MOD 1 = 0 picks 10.
    row("nested mux of literals", "VAR s : SINT; i : INT := 7; END_VAR\ns := MUX(1, s, MUX(i MOD 1, 10, -99));", {"=> s=10", "=> s=10"});
    expr("mux of literals by its destination", "s : SINT; i : INT := 1;", "s := MUX(i, 10, -99);", "s=-99");
    expr("selection of literals in arithmetic", "i : INT := 300; b : BOOL := TRUE; r : INT;", "r := SEL(b, 1, 2) + i;", "r=302");
    expr("not of a literal compared with a word", "w : WORD := 16#FFFE; c : BOOL;", "c := w = NOT 16#0001;", "c=TRUE");
}

// Found by tst_differential: constants folded by the compiler give what the running program
// computes. (2^63 - 1) * 2 wraps to 2^64 - 2 as a ULINT, a large positive LREAL; folded, it was
// taken for -2.
void TestCorrectness::foldedLikeAtRunTime_data()
{
    columns();
    expr("wrapped ulint to lreal", "b : BOOL; c : BOOL; u : ULINT := 2;",
         "b := ULINT_TO_LREAL(ULINT#9223372036854775807 * ULINT#2) > 0.0; c := ULINT_TO_LREAL(ULINT#9223372036854775807 * u) > 0.0;",
         "b=TRUE; c=TRUE");
    // REAL#0.1 is the float nearest 0.1, folded or not: SIN of it as the VM computes it.
    expr("sin of a real constant", "a : REAL; b : REAL; x : REAL := 0.1; e : BOOL;", "a := SIN(REAL#0.1); b := SIN(x); e := a = b;", "a=0.09983342; b=0.09983342; e=TRUE");
    // COS of a REAL is a REAL before it is divided: folded, it was divided with double precision.
    expr("cos of a real constant divided", "a : REAL; b : REAL; x : REAL := 1.5; y : REAL := 1.2247449; e : BOOL;",
         "a := COS(REAL#1.5) / REAL#1.2247449; b := COS(x) / y; e := a = b;", "a=0.057756677; b=0.057756677; e=TRUE");
}

QTEST_GUILESS_MAIN(TestCorrectness)
#include "tst_correctness.moc"
