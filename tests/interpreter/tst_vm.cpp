// Programs run scan by scan with exact values: operators, wraparound, conversions, statements,
// user POUs, strings, times, IL.
#include "tracerunner.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;
using namespace iec::interp::testing::table;

class TestVm : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void arithmetic_data();
    void arithmetic() { check(); }
    void conversions_data();
    void conversions() { check(); }
    void statements_data();
    void statements() { check(); }
    void data_data();
    void data() { check(); }
    void pous_data();
    void pous() { check(); }
    void strings_data();
    void strings() { check(); }
    void timesAndDates_data();
    void timesAndDates() { check(); }
    void standardFunctions_data();
    void standardFunctions() { check(); }
    void instructionList_data();
    void instructionList() { check(); }
    void sameTraceInStAndIl();
};

void TestVm::arithmetic_data()
{
    columns();
    expr("precedence", "x : INT; y : INT; z : INT;", "x := 2 + 3 * 4; y := (2 + 3) * 4; z := 20 - 6 - 4;", "x=14; y=20; z=10");
    expr("power", "r : REAL; l : LREAL; i : INT := 3;", "r := 2.0 ** 3; l := INT_TO_LREAL(i) ** 2;", "r=8.0; l=9.0");
    expr("unary minus before power", "r : LREAL := 2.0; x : LREAL;", "x := -r ** 2;", "x=4.0");
    expr("int wraparound", "x : INT := 32767; y : INT := -32768;", "x := x + 1; y := y - 1;", "x=-32768; y=32767");
    expr("sint wraparound", "x : SINT := 127; y : SINT;", "x := x + 1; y := SINT#-128 - 1;", "x=-128; y=127");
    expr("usint wraparound", "x : USINT := 255; y : UINT;", "x := x + 1; y := y - 1;", "x=0; y=65535");
    expr("dint wraparound", "x : DINT := 2147483647; m : DINT := 65536;", "x := x + 1; m := m * m;", "x=-2147483648; m=0");
    expr("lint multiply wraps", "x : LINT := 4294967296;", "x := x * x * 2;", "x=0");
    expr("udint", "x : UDINT := 4000000000; y : UDINT;", "y := x + x;", "y=3705032704");
    expr("ulint", "x : ULINT := 18446744073709551615; y : ULINT;", "y := x + 2;", "x=18446744073709551615; y=1");
    expr("integer division truncates", "a : INT := -7; q : INT; m : INT; q2 : INT;", "q := a / 2; m := a MOD 2; q2 := 7 / -2;", "q=-3; m=-1; q2=-3");
    expr("min int divided by -1 wraps", "a : INT := -32768; b : INT := -1; q : INT; m : INT;", "q := a / b; m := a MOD b;", "q=-32768; m=0");
    expr("unsigned division", "a : UINT := 65535; b : UINT := 2; q : UINT;", "q := a / b;", "q=32767");
    expr("real arithmetic", "a : REAL := 1.5; b : REAL := 0.25; c : REAL; d : LREAL;", "c := a * b - 1.0; d := 1.0 / 3.0;", "c=-0.625; d=0.3333333333333333");
    expr("real division by zero is infinite", "a : REAL := 1.0; z : REAL; c : REAL;", "c := a / z;", "c=+Inf");
    expr("implicit widening", "i : INT := 1000; d : DINT; r : REAL; l : LREAL; s : SINT := -5;", "d := i * 1000; r := i; l := INT_TO_DINT(i) * 1000; d := s + i;", "d=995; r=1000.0; l=1000000.0");
    expr("widened operands", "i : INT := 300; s : SINT := 100; d : DINT;", "d := i * s;", "d=30000");
    expr("mixed int and real", "i : INT := 3; r : REAL;", "r := i * 1.5;", "r=4.5");
    expr("comparisons", "a : INT := 3; b : INT := 5; c1 : BOOL; c2 : BOOL; c3 : BOOL; c4 : BOOL; c5 : BOOL; c6 : BOOL;",
         "c1 := a < b; c2 := a > b; c3 := a <= 3; c4 := a >= 4; c5 := a = 3; c6 := a <> b;", "c1=TRUE; c2=FALSE; c3=TRUE; c4=FALSE; c5=TRUE; c6=TRUE");
    expr("unsigned comparison", "a : UDINT := 4000000000; b : UDINT := 1; c : BOOL;", "c := a > b;", "c=TRUE");
    expr("boolean logic", "a : BOOL := TRUE; b : BOOL; c : BOOL := TRUE; x : BOOL; y : BOOL; z : BOOL; w : BOOL;",
         "x := a AND NOT b; y := a XOR c; z := b OR NOT c; w := a & c;", "x=TRUE; y=FALSE; z=FALSE; w=TRUE");
    row("rung shapes", "VAR a : BOOL; b : BOOL; c : BOOL; d : BOOL; s : BOOL; p : BOOL; q : BOOL; END_VAR\n"
                       "s := (a AND b) OR c; p := (a OR b) AND c; q := d OR (a AND NOT b) AND c; d := (d AND a) OR (b AND c);",
        {"=> s=FALSE; p=FALSE; q=FALSE; d=FALSE", "a=TRUE; c=TRUE => s=TRUE; p=TRUE; q=TRUE; d=FALSE", "b=TRUE => s=TRUE; p=TRUE; q=FALSE; d=TRUE",
         "a=FALSE; c=FALSE => s=FALSE; p=FALSE; q=TRUE; d=FALSE", "a=TRUE; b=FALSE; c=FALSE => s=FALSE; p=FALSE; q=FALSE; d=FALSE"});
    expr("logic precedence", "a : BOOL := TRUE; b : BOOL; c : BOOL; x : BOOL;", "x := a OR b AND c;", "x=TRUE");
    expr("bit strings", "w : WORD := 16#00F0; b : BYTE := 2#1010_1010; x : WORD; y : BYTE; z : WORD;",
         "x := w OR 16#0F00; y := NOT b; z := w XOR 16#FFFF;", "x=4080; y=85; z=65295");
    expr("bit access read", "w : WORD := 16#0008; b3 : BOOL; b2 : BOOL;", "b3 := w.3; b2 := w.2;", "b3=TRUE; b2=FALSE");
    expr("bit access write", "w : WORD; d : DWORD := 16#FFFF_FFFF;", "w.15 := TRUE; w.0 := TRUE; d.31 := FALSE;", "w=32769; d=2147483647");
    expr("shifts and rotations", "b : BYTE := 16#81; l : BYTE; r : BYTE; sl : BYTE; sr : BYTE; w : WORD := 1; big : WORD;",
         "l := ROL(b, 1); r := ROR(b, 1); sl := SHL(b, 1); sr := SHR(b, 4); big := SHL(w, 16);", "l=3; r=192; sl=2; sr=8; big=0");
    expr("constant folding", "x : INT; y : DINT;", "x := 100 * 3 - 1; y := -(2 + 3) * 7 MOD 4;", "x=299; y=-3");
}

void TestVm::conversions_data()
{
    columns();
    expr("real to int rounds half away from zero", "a : INT; b : INT; c : INT; d : INT; e : DINT;",
         "a := REAL_TO_INT(2.5); b := REAL_TO_INT(-2.5); c := REAL_TO_INT(1.4); d := LREAL_TO_INT(1.6); e := REAL_TO_DINT(-0.5);",
         "a=3; b=-3; c=1; d=2; e=-1");
    expr("real to integer saturates", "big : LREAL := 1.0E300; a : DINT; b : SINT; c : UDINT; d : INT; e : INT; n : LREAL; f : INT;",
         "a := LREAL_TO_DINT(big); b := REAL_TO_SINT(-1000.0); c := LREAL_TO_UDINT(-5.0); d := LREAL_TO_INT(-big); e := REAL_TO_INT(1.0E10); n := SQRT(-1.0); f := LREAL_TO_INT(n);",
         "a=2147483647; b=-128; c=0; d=-32768; e=32767; f=0");
    expr("trunc", "a : DINT; b : INT; r : REAL := -2.7;", "a := TRUNC(r); b := REAL_TRUNC_INT(2.9);", "a=-2; b=2");
    expr("narrowing wraps", "i : INT := 300; s : SINT; d : DINT := 70000; n : INT; u : USINT;", "s := INT_TO_SINT(i); n := DINT_TO_INT(d); u := INT_TO_USINT(-1);", "s=44; n=4464; u=255");
    expr("signed and unsigned", "i : INT := -1; w : WORD; u : UDINT;", "w := INT_TO_WORD(i); u := INT_TO_UDINT(i);", "w=65535; u=4294967295");
    expr("bool conversions", "b : BOOL; i : INT; r : BOOL; x : BYTE;", "i := BOOL_TO_INT(TRUE); b := INT_TO_BOOL(5); r := REAL_TO_BOOL(0.0); x := BOOL_TO_BYTE(TRUE);",
         "i=1; b=TRUE; r=FALSE; x=1");
    expr("int to real", "r : REAL; l : LREAL; i : DINT := 16777217;", "r := DINT_TO_REAL(i); l := DINT_TO_LREAL(i);", "r=16777216.0; l=16777217.0");
    expr("time to numbers", "t : TIME := T#1s500ms; d : DINT; r : REAL; lt : LTIME := LTIME#2us; l : LINT;",
         "d := TIME_TO_DINT(t); r := TIME_TO_REAL(T#1.5ms); l := LTIME_TO_LINT(lt);", "d=1500; r=1.5; l=2000");
    expr("numbers to time", "t : TIME; u : TIME;", "t := DINT_TO_TIME(1500); u := REAL_TO_TIME(2.5);", "t=T#1s500ms; u=T#2ms500us");
    expr("to string", "s1 : STRING; s2 : STRING; s3 : STRING; s4 : STRING; s5 : STRING;",
         "s1 := INT_TO_STRING(-42); s2 := REAL_TO_STRING(1.5); s3 := BOOL_TO_STRING(TRUE); s4 := TIME_TO_STRING(T#1m2s); s5 := DATE_TO_STRING(D#2024-02-29);",
         "s1='-42'; s2='1.5'; s3='TRUE'; s4='T#1m2s'; s5='D#2024-02-29'");
    expr("to string as in the beremiz tests", "a : STRING; b : STRING; c : STRING;", "a := REAL_TO_STRING(42.0); b := WORD_TO_STRING(42); c := LWORD_TO_STRING(16#FF);",
         "a='42'; b='16#2a'; c='16#ff'");
    expr("from string", "i : INT; r : REAL; b : BOOL; t : TIME;", "i := STRING_TO_INT('123'); r := STRING_TO_REAL('2.25'); b := STRING_TO_BOOL('TRUE'); t := STRING_TO_TIME('T#5s');",
         "i=123; r=2.25; b=TRUE; t=T#5s");
    // INT_TO_BCD is CODESYS Util's (a BYTE, 255 outside 0..99); INT_TO_BCD_WORD gives four digits.
    expr("bcd", "w : WORD; i : INT; b : BYTE; v : WORD;", "w := INT_TO_BCD(1234); i := WORD_BCD_TO_INT(16#0987); b := USINT_TO_BCD_BYTE(42); v := INT_TO_BCD_WORD(1234);",
         "w=255; i=987; b=66; v=4660");
    expr("typed literals", "a : INT; b : BOOL; w : WORD; r : REAL;", "a := INT#-5; b := BOOL#1; w := WORD#16#FFFF; r := REAL#2;", "a=-5; b=TRUE; w=65535; r=2.0");
    expr("enum conversion", "TYPE_UNUSED : INT;", ";", "TYPE_UNUSED=0");
}

void TestVm::statements_data()
{
    columns();
    row("if elsif else", "VAR a : INT; c : INT; END_VAR\nIF a < 0 THEN c := -1; ELSIF a = 0 THEN c := 0; ELSIF a < 10 THEN c := 1; ELSE c := 2; END_IF;",
        {"a=-5 => c=-1", "a=0 => c=0", "a=7 => c=1", "a=10 => c=2"});
    row("case lists and ranges",
        "VAR i : INT; c : INT; END_VAR\nCASE i OF 1, 2, 3, 5: c := 1; 4: c := 2; 10..20: c := 3; ELSE c := 0; END_CASE;",
        {"i=2 => c=1", "i=4 => c=2", "i=15 => c=3", "i=20 => c=3", "i=21 => c=0", "i=5 => c=1"});
    // CODESYS state machines call their state Step: only "STEP name" starts textual SFC.
    row("Step, Transition and Action as variable names",
        "VAR Step : INT; Action : BOOL; Transition : INT; END_VAR\nStep := Step + 1;\nAction := Step > 2;\n"
        "CASE Step OF 1: Transition := 5; 3: Transition := Transition * 2; END_CASE;",
        {"=> Step=1; Action=FALSE; Transition=5", "=> Step=2", "=> Step=3; Action=TRUE; Transition=10"});
    row("NOT of a literal takes the bit string it is assigned to", "VAR b : BYTE; w : WORD; d : DWORD; END_VAR\nb := NOT 16#0F;\nw := NOT 0;\nd := NOT 1;",
        {"=> b=240; w=65535; d=4294967294"});
    row("case without else keeps value", "VAR i : INT; c : INT := 9; END_VAR\nCASE i OF 1: c := 1; END_CASE;", {"i=3 => c=9", "i=1 => c=1"});
    row("for", "VAR i : INT; s : INT; END_VAR\ns := 0; FOR i := 1 TO 10 DO s := s + i; END_FOR;", {"=> s=55; i=11"});
    row("for by negative", "VAR i : INT; s : INT; END_VAR\ns := 0; FOR i := 10 TO 1 BY -3 DO s := s * 10 + i; END_FOR;", {"=> s=10741; i=-2"});
    row("for by variable", "VAR i : INT; st : INT := -2; n : INT; END_VAR\nn := 0; FOR i := 5 TO 0 BY st DO n := n + 1; END_FOR;", {"=> n=3"});
    row("for not entered", "VAR i : INT; n : INT; END_VAR\nFOR i := 5 TO 1 DO n := n + 1; END_FOR;", {"=> n=0; i=5"});
    row("for seed example", "VAR Counter : INT; Var1 : INT := 1; Erg : INT; END_VAR\nFOR Counter := 1 TO 4 BY 1 DO Var1 := Var1 * 2; END_FOR; Erg := Var1;", {"=> Erg=16"});
    row("while", "VAR Counter : INT := 10; Var1 : INT := 1; Var2 : INT; END_VAR\nWHILE Counter <> 0 DO Var1 := Var1 * 2; Counter := Counter - 1; END_WHILE; Var2 := Var1;",
        {"=> Var2=1024"});
    row("repeat runs once", "VAR j : INT; n : INT; END_VAR\nREPEAT n := n + 1; UNTIL TRUE END_REPEAT;", {"=> n=1", "=> n=2"});
    row("repeat", "VAR j : INT; END_VAR\nj := -11; REPEAT j := j + 2; UNTIL j = 51 END_REPEAT;", {"=> j=51"});
    row("exit", "VAR i : INT; J : INT; ARR : ARRAY[1..100] OF INT; END_VAR\nARR[51] := 50; J := 101; FOR i := 1 TO 100 BY 2 DO IF ARR[i] = 50 THEN J := i; EXIT; END_IF; END_FOR;",
        {"=> J=51"});
    row("exit leaves the inner loop only", "VAR i : INT; k : INT; n : INT; END_VAR\nn := 0; FOR i := 1 TO 3 DO FOR k := 1 TO 10 DO IF k = 3 THEN EXIT; END_IF; n := n + 1; END_FOR; END_FOR;",
        {"=> n=6"});
    row("continue", "VAR i : INT; n : INT; END_VAR\nn := 0; FOR i := 1 TO 10 DO IF i MOD 2 = 0 THEN CONTINUE; END_IF; n := n + i; END_FOR;", {"=> n=25"});
    row("continue in while and repeat", "VAR i : INT; n : INT; j : INT; m : INT; END_VAR\n"
        "i := 0; n := 0; WHILE i < 10 DO i := i + 1; IF i MOD 3 = 0 THEN CONTINUE; END_IF; n := n + 1; END_WHILE;\n"
        "j := 0; m := 0; REPEAT j := j + 1; IF j = 2 THEN CONTINUE; END_IF; m := m + j; UNTIL j >= 4 END_REPEAT;",
        {"=> n=7; m=8"});
    row("return", "VAR a : INT; b : INT; END_VAR\na := 1; IF a = 1 THEN RETURN; END_IF; b := 5;", {"=> a=1; b=0"});
    row("values persist between cycles", "VAR n : INT; END_VAR\nn := n + 1;", {"=> n=1", "=> n=2", "=> n=3"});
    // Loops whose step and test become one instruction (IncBr*): each comparison, not entered,
    // step read from a variable, wraparound of the step, and an IF that jumps to the test.
    row("while step fused <=", "VAR j : INT; n : INT; s : INT := 3; END_VAR\nj := 1; n := 0; WHILE j <= 10 DO n := n + j; j := j + s; END_WHILE;", {"=> n=22; j=13"});
    row("while step fused <", "VAR j : DINT; n : DINT; END_VAR\nj := 0; n := 0; WHILE j < 10 DO n := n + 1; j := 2 + j; END_WHILE;", {"=> n=5; j=10"});
    row("while step fused >= and >", "VAR j : INT; n : INT; k : INT; m : INT; END_VAR\nj := 10; n := 0; WHILE j >= 0 DO n := n + 1; j := j - 3; END_WHILE;\n"
        "k := 10; m := 0; WHILE k > 0 DO m := m + 1; k := k + -4; END_WHILE;", {"=> n=4; j=-2; m=3; k=-2"});
    row("while not entered", "VAR j : INT := 50; n : INT; END_VAR\nWHILE j <= 10 DO n := n + 1; j := j + 1; END_WHILE;", {"=> n=0; j=50"});
    row("while step wraps", "VAR j : SINT; n : INT; END_VAR\nj := 120; n := 0; WHILE j > 100 DO n := n + 1; j := j + 5; END_WHILE;", {"=> n=2; j=-126"});
    row("while step inside if is not fused", "VAR j : INT; n : INT; END_VAR\nj := 0; n := 0; WHILE j < 4 AND n < 100 DO n := n + 1; IF n MOD 2 = 0 THEN j := j + 1; END_IF; END_WHILE;",
        {"=> n=8; j=4"});
    row("while step then test of another variable", "VAR j : INT; k : INT; END_VAR\nj := 0; k := 0; WHILE k < 3 DO k := k + 1; j := j + 1; END_WHILE;", {"=> j=3; k=3"});
    // Multiply and add in one instruction (MulAdd): wraparound and REAL rounding as two steps.
    expr("muladd int wraps", "a : INT := 300; b : INT := 300; c : INT := 7; r : INT; s : INT;", "r := a * b + c; s := c + a * b;", "r=24471; s=24471");
    expr("muladd real", "x : REAL := 1.5; y : REAL := 2.0; z : REAL := 0.25; r : REAL; s : LREAL := 0.5;", "r := x * y + z; s := s + LREAL#3.0 * s;", "r=3.25; s=2.0");
    expr("muladd index", "a : ARRAY[0..11] OF INT; i : INT := 2; j : INT := 3; v : INT; w : INT;",
         "a[i * 4 + j] := 7; v := a[11]; w := a[i * 4 + j] + a[j * 1 + 0];", "v=7; w=7");
    expr("muladd index wraps", "a : ARRAY[0..3] OF DINT := [1, 2, 3, 4]; i : INT := 16384; v : DINT;", "v := a[i * 4 + 2];", "v=3");
    // Rungs: (a AND NOT b) OR (c AND d) in one instruction, on variables and on temporaries.
    expr("rung fused", "a : BOOL := TRUE; b : BOOL; c : BOOL; d : BOOL := TRUE; k : INT := 1; o : BOOL; p : BOOL; q : BOOL;",
         "o := (a AND NOT b) OR (c AND d); p := (a AND NOT a) OR (d AND (c OR a)); q := ((k > 0) AND NOT a) OR (d AND (k < 0));", "o=TRUE; p=TRUE; q=FALSE");
    // Ten rungs in a row run as one RungBlock; each reads the one computed just before it.
    row("rung block", "VAR a : BOOL := TRUE; b : BOOL; c : BOOL := TRUE; o0, o1, o2, o3, o4, o5, o6, o7, o8, o9 : BOOL; END_VAR\no0 := (a AND NOT b) OR (c AND o9); o1 := (o0 AND NOT a) OR (c AND o0); o2 := (o1 AND NOT a) OR (c AND o1); o3 := (o2 AND NOT a) OR (c AND o2); o4 := (o3 AND NOT a) OR (c AND o3); o5 := (o4 AND NOT a) OR (c AND o4); o6 := (o5 AND NOT a) OR (c AND o5); o7 := (o6 AND NOT a) OR (c AND o6); o8 := (o7 AND NOT a) OR (c AND o7); o9 := (o8 AND NOT a) OR (c AND o8);",
        {"=> o0=TRUE; o5=TRUE; o9=TRUE", "a=FALSE; b=TRUE => o0=TRUE; o9=TRUE", "c=FALSE => o0=FALSE; o1=FALSE; o9=FALSE", "a=TRUE; b=FALSE => o0=TRUE; o1=FALSE; o9=FALSE"});
    expr("rung fused false", "a : BOOL := TRUE; b : BOOL := TRUE; c : BOOL := TRUE; d : BOOL; o : BOOL := TRUE;", "o := (a AND NOT b) OR (c AND d);", "o=FALSE");
}

void TestVm::data_data()
{
    columns();
    row("array initial values with repetition", "VAR a : ARRAY[1..5] OF INT := [1, 2(7), 3]; s : INT; i : INT; END_VAR\nFOR i := 1 TO 5 DO s := s * 10 + a[i]; END_FOR;",
        {"=> s=17730; a=[1, 7, 7, 3, 0]"});
    row("two-dimensional array", "VAR m : ARRAY[0..2, 1..3] OF INT; i : INT; j : INT; x : INT; END_VAR\n"
                                 "FOR i := 0 TO 2 DO FOR j := 1 TO 3 DO m[i, j] := i * 10 + j; END_FOR; END_FOR; x := m[2, 3] + m[1, 1];",
        {"=> x=34; m[1,2]=12"});
    row("array of structs", "TYPE Pt : STRUCT x : INT; y : INT := 7; END_STRUCT; END_TYPE\n"
                            "PROGRAM Main VAR p : ARRAY[1..3] OF Pt := [(x := 1), (x := 2, y := 3)]; i : INT := 2; s : INT; END_VAR\n"
                            "p[i].x := p[i].x + 10; s := p[1].x + p[1].y + p[2].x + p[2].y + p[3].y;\nEND_PROGRAM",
        {"=> s=30; p[2].x=12"});
    row("struct assignment copies", "TYPE Pt : STRUCT x : INT; y : INT; END_STRUCT; END_TYPE\n"
                                    "PROGRAM Main VAR a : Pt := (x := 1, y := 2); b : Pt; END_VAR\nb := a; a.x := 5;\nEND_PROGRAM",
        {"=> b.x=1; b.y=2; a.x=5"});
    row("enum", "TYPE Color : (Red, Green := 5, Blue); END_TYPE\n"
                "PROGRAM Main VAR c : Color; n : INT; d : Color := Blue; END_VAR\n"
                "IF c = Red THEN n := 1; END_IF; c := Color#Green; CASE d OF Red: n := n + 10; Blue: n := n + 100; END_CASE;\nEND_PROGRAM",
        {"=> n=101; c=Color#Green; d=Color#Blue"});
    row("enum values qualified with a dot (CODESYS)", "TYPE Mode : (Idle, Run); END_TYPE\n"
                                                     "PROGRAM Main VAR m : Mode; n : INT; END_VAR\n"
                                                     "CASE m OF Mode.Idle: n := 1; m := Mode.Run; Mode.Run: n := 2; END_CASE;\nEND_PROGRAM",
        {"=> n=1; m=Mode#Run", "=> n=2"});
    row("subrange and alias", "TYPE Pct : INT (0..100) := 50; Counter : DINT; END_TYPE\n"
                              "PROGRAM Main VAR p : Pct; c : Counter := 3; END_VAR\np := p + 1; c := c * 2;\nEND_PROGRAM",
        {"=> p=51; c=6"});
    row("constants", "VAR CONSTANT N : INT := 4; END_VAR VAR a : ARRAY[1..N] OF INT; s : INT; i : INT; END_VAR\nFOR i := 1 TO N DO a[i] := i; s := s + a[i]; END_FOR;",
        {"=> s=10"});
    row("global variables", "VAR_GLOBAL g : INT := 5; END_VAR\nPROGRAM Main VAR_EXTERNAL g : INT; END_VAR VAR x : INT; END_VAR\ng := g + 1; x := g;\nEND_PROGRAM",
        {"=> x=6; g=6", "=> x=7"});
    row("located variables", "VAR in0 AT %IX0.0 : BOOL; out1 AT %QX0.1 : BOOL; w AT %QW1 : WORD; END_VAR\nout1 := NOT in0; w := 16#1234; %QX0.3 := in0;",
        {"=> %QX0.1=TRUE; %QX0.3=FALSE; %QW1=4660", "%IX0.0=TRUE => %QX0.1=FALSE; %QX0.3=TRUE; out1=FALSE"});
    row("string type", "TYPE Name : STRING[4]; END_TYPE\nPROGRAM Main VAR n : Name := 'ab'; m : INT; END_VAR\nn := CONCAT(n, 'c'); m := LEN(n);\nEND_PROGRAM",
        {"=> n='abc'; m=3"});
    row("memory addresses", "VAR w AT %MW2 : UINT; END_VAR\nw := w + 1; %MX10.0 := TRUE;", {"=> %MW2=1; %MX10.0=TRUE", "=> %MW2=2"});
    row("strings in structs and arrays", "VAR names : ARRAY[1..2] OF STRING[8] := ['ab', 'cd']; i : INT := 2; s : STRING; END_VAR\nnames[i] := CONCAT(names[i], 'x'); s := names[2];",
        {"=> s='cdx'", "=> s='cdxx'"});
}

void TestVm::pous_data()
{
    columns();
    // CODESYS actions: called inside the POU, on FB instances from outside, from IL with CAL.
    row("action inside the program", "PROGRAM Main\nVAR n : INT; END_VAR\nn := n + 1; IF n = 3 THEN Reset(); END_IF;\n"
        "ACTION Reset:\nn := 100;\nEND_ACTION\nEND_PROGRAM", {"=> n=1", "=> n=2", "=> n=100", "=> n=101"});
    row("action of an instance",
        "FUNCTION_BLOCK Counter\nVAR_OUTPUT cv : INT; END_VAR\ncv := cv + 1;\nACTION Clear:\ncv := 0;\nEND_ACTION\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR c1 : Counter; c2 : Counter; a : INT; b : INT; END_VAR\nc1(); c2(); c2(); IF c1.cv >= 2 THEN c1.Clear(); END_IF; a := c1.cv; b := c2.cv;\nEND_PROGRAM",
        {"=> a=1; b=2", "=> a=0; b=4", "=> a=1; b=6"});
    row("action called with CAL in IL",
        "FUNCTION_BLOCK Lamp\nVAR_OUTPUT on : BOOL; END_VAR\nACTION Switch:\non := NOT on;\nEND_ACTION\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR l : Lamp; x : BOOL; END_VAR\nCAL l.Switch\nLD l.on\nST x\nEND_PROGRAM",
        {"=> x=TRUE", "=> x=FALSE"});
    row("IL action inside its POU",
        "PROGRAM Main\nVAR n : INT; END_VAR\nCAL Bump\nCAL Bump\nACTION Bump:\nLD n\nADD 1\nST n\nEND_ACTION\nEND_PROGRAM", {"=> n=2", "=> n=4"});
    row("function positional and formal",
        "FUNCTION Scale : REAL VAR_INPUT x : REAL; k : REAL := 2.0; END_VAR Scale := x * k; END_FUNCTION\n"
        "PROGRAM Main VAR a : REAL; b : REAL; c : REAL; END_VAR\na := Scale(1.5, 3.0); b := Scale(x := 4.0); c := Scale(k := 10.0, x := Scale(1.0));\nEND_PROGRAM",
        {"=> a=4.5; b=8.0; c=20.0"});
    row("function locals start fresh",
        "FUNCTION Inc : INT VAR_INPUT x : INT; END_VAR VAR n : INT; END_VAR n := n + x; Inc := n; END_FUNCTION\n"
        "PROGRAM Main VAR a : INT; b : INT; END_VAR\na := Inc(5); b := Inc(5) + Inc(1);\nEND_PROGRAM",
        {"=> a=5; b=6"});
    row("function outputs and in out",
        "FUNCTION Split : BOOL VAR_INPUT v : INT; END_VAR VAR_OUTPUT hi : INT; lo : INT; END_VAR VAR_IN_OUT total : INT; END_VAR\n"
        "hi := v / 100; lo := v MOD 100; total := total + v; Split := TRUE; END_FUNCTION\n"
        "PROGRAM Main VAR h : INT; l : INT; t : INT := 1; ok : BOOL; END_VAR\nok := Split(v := 1234, hi => h, lo => l, total := t);\nEND_PROGRAM",
        {"=> h=12; l=34; t=1235; ok=TRUE", "=> t=2469"});
    row("function block with state",
        "FUNCTION_BLOCK Acc VAR_INPUT x : INT; END_VAR VAR_OUTPUT sum : INT; END_VAR sum := sum + x; END_FUNCTION_BLOCK\n"
        "PROGRAM Main VAR a : Acc; b : Acc; s : INT; END_VAR\na(x := 2); b(x := 5); s := a.sum * 100 + b.sum;\nEND_PROGRAM",
        {"=> s=205", "=> s=410"});
    row("nested instances",
        "FUNCTION_BLOCK Inner VAR_INPUT i : INT; END_VAR VAR_OUTPUT Out : INT; END_VAR Out := i * 2; END_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK Outer VAR_INPUT i : INT; END_VAR VAR Sub : Inner; END_VAR VAR_OUTPUT o : INT; END_VAR Sub(i := i + 1); o := Sub.Out; END_FUNCTION_BLOCK\n"
        "PROGRAM Main VAR Inst : Outer; v : INT; w : INT; END_VAR\nInst(i := 4); v := Inst.Sub.Out; w := Inst.o;\nEND_PROGRAM",
        {"=> v=10; w=10; Inst.Sub.i=5"});
    row("fb outputs with =>",
        "FUNCTION_BLOCK Pair VAR_OUTPUT a : INT; b : BOOL; END_VAR a := a + 1; b := NOT b; END_FUNCTION_BLOCK\n"
        "PROGRAM Main VAR p : Pair; x : INT; y : BOOL; z : BOOL; END_VAR\np(a => x, b => y, NOT b => z);\nEND_PROGRAM",
        {"=> x=1; y=TRUE; z=FALSE", "=> x=2; y=FALSE; z=TRUE"});
    row("fb input set by member assignment",
        "PROGRAM Main VAR t : TON; q : BOOL; END_VAR\nt.IN := TRUE; t.PT := T#20ms; t(); q := t.Q;\nEND_PROGRAM",
        {"=> q=FALSE", "=> q=FALSE", "=> q=TRUE"});
    row("array of fb instances",
        "PROGRAM Main VAR c : ARRAY[1..3] OF CTU; i : INT; n : INT; pulse : BOOL; END_VAR\n"
        "pulse := NOT pulse; FOR i := 1 TO 3 DO c[i](CU := pulse AND i <> 2, PV := 2); END_FOR; n := c[1].CV * 10 + c[2].CV;\nEND_PROGRAM",
        {"=> n=10", "=> n=10", "=> n=20; c[1].Q=TRUE; c[2].Q=FALSE"});
    row("var_temp starts fresh on every call",
        "FUNCTION_BLOCK Tmp VAR_OUTPUT o : INT; END_VAR VAR_TEMP t : INT := 5; END_VAR VAR keep : INT; END_VAR\n"
        "t := t + 1; keep := keep + 1; o := t * 100 + keep; END_FUNCTION_BLOCK\n"
        "PROGRAM Main VAR f : Tmp; END_VAR\nf();\nEND_PROGRAM",
        {"=> f.o=601", "=> f.o=602"});
    row("function returning a string",
        "FUNCTION Greet : STRING[20] VAR_INPUT name : STRING[10]; END_VAR Greet := CONCAT('Hi ', name); END_FUNCTION\n"
        "PROGRAM Main VAR s : STRING[20]; n : INT; END_VAR\ns := Greet('Bob'); n := LEN(Greet('Alice'));\nEND_PROGRAM",
        {"=> s='Hi Bob'; n=8"});
    row("function returning a structure",
        "TYPE Pt : STRUCT x : INT; y : INT; END_STRUCT; END_TYPE\n"
        "FUNCTION Mid : Pt VAR_INPUT a : Pt; b : Pt; END_VAR Mid.x := (a.x + b.x) / 2; Mid.y := (a.y + b.y) / 2; END_FUNCTION\n"
        "PROGRAM Main VAR p : Pt := (x := 2, y := 4); q : Pt := (x := 6, y := 10); m : Pt; END_VAR\nm := Mid(p, q);\nEND_PROGRAM",
        {"=> m.x=4; m.y=7"});
    row("fb in out", "FUNCTION_BLOCK Bump VAR_IN_OUT v : INT; END_VAR v := v + 1; END_FUNCTION_BLOCK\n"
                     "PROGRAM Main VAR b : Bump; a : ARRAY[1..2] OF INT; k : INT := 2; END_VAR\nb(v := a[k]); b(v := a[1]);\nEND_PROGRAM",
        {"=> a=[1, 1]", "=> a=[2, 2]"});
}

void TestVm::strings_data()
{
    columns();
    expr("string functions", "s : STRING := 'Hello World'; n : INT; l : STRING; r : STRING; m : STRING; f : INT; g : INT;",
         "n := LEN(s); l := LEFT(s, 5); r := RIGHT(s, 5); m := MID(s, 3, 2); f := FIND(s, 'World'); g := FIND(s, 'xyz');",
         "n=11; l='Hello'; r='World'; m='ell'; f=7; g=0");
    expr("insert delete replace", "s : STRING := 'abcdef'; i : STRING; d : STRING; r : STRING;",
         "i := INSERT(s, 'XY', 2); d := DELETE(s, 2, 3); r := REPLACE(s, 'Z', 3, 2);", "i='abXYcdef'; d='abef'; r='aZef'");
    expr("concat extensible", "a : STRING := 'x'; s : STRING;", "s := CONCAT(a, '-', 'y', '$$');", "s='x-y$$'");
    expr("string comparison", "a : STRING := 'abc'; b : STRING := 'abd'; lt : BOOL; eq : BOOL; ne : BOOL;",
         "lt := a < b; eq := a = 'abc'; ne := a <> b;", "lt=TRUE; eq=TRUE; ne=TRUE");
    expr("escapes", "s : STRING; n : INT;", "s := 'it$'s$N'; n := LEN(s);", "n=5; s='it$'s$N'");
    expr("wide strings", "w : WSTRING := \"\u00e4\u00f6\"; n : INT; c : WSTRING;", "n := LEN(w); c := CONCAT(w, \"$00FC\");", "n=2; c=\"\u00e4\u00f6\u00fc\"");
    expr("string to wstring", "s : STRING := 'ab'; w : WSTRING;", "w := STRING_TO_WSTRING(s);", "w=\"ab\"");
}

void TestVm::timesAndDates_data()
{
    columns();
    expr("time arithmetic", "a : TIME := T#1s; b : TIME; c : TIME; d : TIME; e : TIME;",
         "b := a + T#500ms; c := a - T#1500ms; d := a * 3; e := a / 4;", "b=T#1s500ms; c=T#-500ms; d=T#3s; e=T#250ms");
    expr("time times real", "a : TIME := T#1s; b : TIME;", "b := a * 1.5;", "b=T#1s500ms");
    expr("time comparison", "a : TIME := T#1m; c : BOOL;", "c := a > T#59s999ms;", "c=TRUE");
    expr("time of day and date", "t : TOD := TOD#12:00:00; d : DATE := D#2024-03-01; dt1 : DT; x : TIME; t2 : TOD; days : TIME;",
         "t2 := t + T#1h30m; dt1 := CONCAT_DATE_TOD(d, t2); x := DT#2024-03-02-00:00:00 - dt1; days := d - D#2024-02-28;",
         "t2=TOD#13:30:00; dt1=DT#2024-03-01-13:30:00; x=T#10h30m; days=T#2d");
    expr("dt split", "dt1 : DT := DT#2024-01-31-23:59:59.5; d : DATE; t : TOD;", "d := DT_TO_DATE(dt1); t := DT_TO_TOD(dt1);",
         "d=D#2024-01-31; t=TOD#23:59:59.5");
    expr("time functions", "a : TIME; b : TOD; c : TIME;", "a := ADD_TIME(T#1s, T#2s); b := ADD_TOD_TIME(TOD#01:00:00, T#30m); c := MUL_TIME(T#2s, 3);",
         "a=T#3s; b=TOD#01:30:00; c=T#6s");
    expr("ltime", "a : LTIME := LTIME#1ms; b : LTIME;", "b := a + LTIME#1ns;", "b=LT#1ms1ns");
}

void TestVm::standardFunctions_data()
{
    columns();
    expr("numeric", "a : INT; b : REAL; c : LREAL; d : REAL; e : REAL; f : LREAL;",
         "a := ABS(-7); b := ABS(-2.5); c := SQRT(16.0); d := EXPT(2.0, 10); e := LN(1.0); f := LOG(1000.0);", "a=7; b=2.5; c=4.0; d=1024.0; e=0.0; f=3.0");
    expr("trigonometry", "s : LREAL; c : LREAL; t : LREAL; x : LREAL;", "s := SIN(0.0); c := COS(0.0); t := ATAN(1.0) * 4.0; x := EXP(0.0);",
         "s=0.0; c=1.0; t=3.141592653589793; x=1.0");
    expr("extensible arithmetic", "a : INT; m : DINT; s : INT; q : INT; r : INT; v : INT := 7;",
         "a := ADD(1, 2, 3, 4); m := MUL(2, 3, 4); s := SUB(10, 3); q := DIV(v, 2); r := MOD(v, 4);", "a=10; m=24; s=7; q=3; r=3");
    expr("selection", "a : INT := 7; b : INT := -3; mx : INT; mn : INT; l1 : INT; l2 : INT; s1 : INT; m : INT; k : INT := 2;",
         "mx := MAX(a, b, 12, 4); mn := MIN(a, b); l1 := LIMIT(0, a, 5); l2 := LIMIT(MN := 0, IN := b, MX := 5); s1 := SEL(a > 0, 10, 20); m := MUX(k, 100, 200, 300);",
         "mx=12; mn=-3; l1=5; l2=0; s1=20; m=300");
    expr("extensible comparison", "a : BOOL; b : BOOL; c : BOOL; d : BOOL;", "a := GT(5, 3, 1); b := GT(5, 3, 4); c := EQ(2, 2, 2); d := NE(1, 2);",
         "a=TRUE; b=FALSE; c=TRUE; d=TRUE");
    expr("bit functions", "x : BYTE; y : WORD; n : BYTE;", "x := AND(16#F0, 16#3C); y := XOR(WORD#1, 2, 4); n := NOT(BYTE#0);", "x=48; y=7; n=255");
    expr("move", "a : INT := 5; b : INT;", "b := MOVE(a);", "b=5");
}

void TestVm::instructionList_data()
{
    columns();
    row("seed deferred operation", "VAR ERG : INT; END_VAR\nLD 5\nMUL (6\nADD 7\n)\nST ERG", {"=> ERG=65"});
    row("seed without brackets", "VAR ERG : INT; END_VAR\nLD 5\nMUL 6\nADD 7\nST ERG", {"=> ERG=37"});
    row("seed loop", "VAR Counter : INT := 10; Var1 : INT := 1; Var2 : INT; END_VAR\n"
                     "Loop:\n LD Counter\n NE 0\n NOT\n JMPC End_Loop\n LD Var1\n MUL 2\n ST Var1\n LD Counter\n SUB 1\n ST Counter\n JMP Loop\n"
                     "End_Loop:\n LD Var1\n ST Var2",
        {"=> Var2=1024"});
    row("seed jump example", "VAR A : INT := 10; B : INT := 50; C : INT; END_VAR\n"
                             " LD 100\n SUB A\n GE B\n JMPC Next1\n LD A\n ADD B\n ST C\n JMP Next2\nNext1:\n LD A\n SUB B\n ST C\nNext2:",
        {"=> C=-40", "A=60 => C=110"});
    row("modifiers", "VAR BOOL1 : BOOL; BOOL2 : BOOL; ERG : BOOL; X : BOOL; END_VAR\n"
                     " LD TRUE\n ANDN BOOL1\n JMPC example\n LDN BOOL2\n ST ERG\nexample:\n LD BOOL2\n ST ERG\n LD BOOL1\n ORN BOOL2\n XORN FALSE\n STN X",
        {"=> ERG=FALSE; X=TRUE", "BOOL1=TRUE; BOOL2=TRUE => ERG=TRUE; X=TRUE"});
    row("set and reset", "VAR a : BOOL; q : BOOL; END_VAR\n LD a\n S q\n LDN a\n AND q\n R q", {"a=TRUE => q=TRUE", "a=FALSE => q=FALSE"});
    row("nested brackets", "VAR r : INT; END_VAR\n LD 2\n ADD (3\n MUL (4\n SUB 1\n )\n )\n ST r", {"=> r=11"});
    row("bracket with load", "VAR a : BOOL := TRUE; b : BOOL; c : BOOL := TRUE; r : BOOL; END_VAR\n LD a\n AND(\n LD b\n OR c\n )\n ST r", {"=> r=TRUE"});
    row("seed pulse generator with timers", "VAR T1 : TON; T2 : TON; N : BOOL; M : BOOL; ET : TIME; END_VAR\n"
                                            " LD %IX0.0\n ANDN N\n ST T1.IN\n CAL T1(PT := T#30ms)\n LD T1.ET\n ST ET\n LD T1.Q\n ST M\n"
                                            " LD M\n ST T2.IN\n CAL T2(PT := T#20ms)\n LD T2.Q\n ST N\n LD M\n ST %QX0.0",
        {"%IX0.0=TRUE => M=FALSE", "=> ET=T#10ms", "=> ET=T#20ms", "=> M=TRUE; %QX0.0=TRUE", "=> M=TRUE", "=> M=TRUE; N=TRUE", "=> M=FALSE; N=FALSE", "=> M=FALSE; ET=T#0s", "=> ET=T#10ms"});
    row("label between a comparison and its jump", "VAR x : INT := 10; r : INT; n : INT; END_VAR\n"
                                                   " LD x\n GT 5\nL: JMPC Done\n LD 1\n ST r\n RET\nDone:\n LD n\n ADD 1\n ST n\n LD n\n LT 3\n JMP L",
        {"=> n=3; r=1", "=> n=4; r=1"});
    row("label between NOT and AND", "VAR a : BOOL := TRUE; b : BOOL; r : BOOL; k : INT; END_VAR\n"
                                     " LDN b\n JMP M\nBack:\n LD FALSE\nM: AND a\n ST r\n LD k\n ADD 1\n ST k\n LD k\n EQ 1\n JMPC Back",
        {"=> r=FALSE; k=2"});
    row("literals, times, strings and functions in IL", "VAR r : REAL; r2 : REAL; t : TIME; s : STRING; b : BOOL; a : INT := 4; w : WORD := 16#F0; n : INT; END_VAR\n"
        " LD 1.5\n ST r\n LD 5\n ST r2\n LD T#1s\n ADD T#2s\n ST t\n LD 'abc'\n ST s\n"
        " LD 10\n GT( a\n ADD 1\n )\n ST b\n LD w\n AND 16#3C\n SHL 2\n ST w\n LD s\n LEN\n ST n",
        {"=> r=1.5; r2=5.0; t=T#3s; s='abc'; b=TRUE; w=192; n=3"});
    row("function call with operands", "VAR g : BOOL := TRUE; x : INT; m : INT; END_VAR\n LD g\n SEL 10, 20\n ST x\n LD 7\n MAX 3, 12\n ST m", {"=> x=20; m=12"});
    row("conditional call and return", "VAR c : CTU; go : BOOL; n : INT; END_VAR\n LD go\n CALC c(CU := TRUE)\n LD c.CV\n ST n\n LD TRUE\n RETC\n LD 99\n ST n",
        {"go=TRUE => n=1", "go=FALSE => n=1"});
    row("fb input operator", "VAR FF28 : SR; C : INT; D : INT := 5; q : BOOL; END_VAR\n LD C\n LT D\n S1 FF28\n LD FF28.Q1\n ST q", {"=> q=TRUE"});
}

void TestVm::sameTraceInStAndIl()
{
    // The same behaviour written in two languages gives the same trace, cycle by cycle.
    const QString st = QStringLiteral(
        "VAR start : BOOL; stop : BOOL; motor : BOOL; t : TON; count : INT; level : INT; alarm : BOOL; END_VAR\n"
        "motor := (start OR motor) AND NOT stop;\n"
        "t(IN := motor, PT := T#30ms);\n"
        "IF t.Q THEN count := count + 1; END_IF;\n"
        "level := (level + 7) MOD 50;\n"
        "alarm := level > 40 OR count >= 3;");
    const QString il = QStringLiteral(
        "VAR start : BOOL; stop : BOOL; motor : BOOL; t : TON; count : INT; level : INT; alarm : BOOL; END_VAR\n"
        " LD start\n OR motor\n ANDN stop\n ST motor\n"
        " CAL t(IN := motor, PT := T#30ms)\n"
        " LD t.Q\n JMPCN skip\n LD count\n ADD 1\n ST count\nskip:\n"
        " LD level\n ADD 7\n MOD 50\n ST level\n"
        " LD level\n GT 40\n OR( count\n GE 3\n )\n ST alarm");
    const QStringList inputs{QStringLiteral("start=TRUE"), QString(), QStringLiteral("start=FALSE"), QString(), QString(), QString(),
                             QStringLiteral("stop=TRUE"), QStringLiteral("stop=FALSE"), QStringLiteral("start=TRUE"), QString(),
                             QString(), QString(), QString(), QString()};
    // Run the ST version, record its outputs, then require the IL version to produce them.
    Diagnostics diagnostics;
    const QString program = QStringLiteral("PROGRAM Main\n") + st + QStringLiteral("\nEND_PROGRAM");
    Runtime runtime(compileText(program, diagnostics));
    QStringList steps;
    for (const QString &in : inputs) {
        if (!in.isEmpty())
            QVERIFY(!runtime.write(QStringLiteral("Main.") + in.section(QLatin1Char('='), 0, 0), in.section(QLatin1Char('='), 1)));
        QVERIFY(runtime.runCycle());
        QStringList expected;
        for (const char *name : {"motor", "count", "level", "alarm"})
            expected << QLatin1String(name) + QLatin1Char('=') + runtime.read(QStringLiteral("Main.") + QLatin1String(name)).value();
        steps << in + QStringLiteral(" => ") + expected.join(QStringLiteral("; "));
    }
    QCOMPARE(runtime.read(QStringLiteral("Main.count")).value(), QStringLiteral("6")); // the trace is not trivial
    QCOMPARE(runTrace(il, steps), QString());
}

QTEST_GUILESS_MAIN(TestVm)
#include "tst_vm.moc"
