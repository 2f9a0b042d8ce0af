// Audit of literals, types, standard functions and standard function blocks: exact values per
// scan, each row written for a bug found (or a behaviour pinned down) while auditing issue 4.
#include "tracerunner.h"

#include "interpreter/runtime/valueformat.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;
using namespace iec::interp::testing::table;

class TestStdlibAudit : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void literals_data();
    void literals() { check(); }
    void standardFunctions_data();
    void standardFunctions() { check(); }
    void conversions_data();
    void conversions() { check(); }
    void functionBlocks_data();
    void functionBlocks() { check(); }
    void realsPrintAsFloats_data();
    void realsPrintAsFloats();
    void wrongCharLiteral();
    void writesOfEnumsAndChars_data();
    void writesOfEnumsAndChars();
    void inputVariablesAreWrittenInTheImage();
};

void TestStdlibAudit::literals_data()
{
    columns();
    expr("based integers with underscores", "a : INT := 2#1010_1010; b : INT := 8#777; c : DINT := 16#FF_FF; d : INT := -16#10;", "",
         "a=170; b=511; c=65535; d=-16");
    expr("typed integer literals", "d : INT := INT#5; e : BOOL := BOOL#1; f : UINT := UINT#16#FF; z : WORD := WORD#2#1111;", "",
         "d=5; e=TRUE; f=255; z=15");
    expr("extreme 64-bit literals", "w : LINT := LINT#-9223372036854775808; x : ULINT := 18446744073709551615;", "",
         "w=-9223372036854775808; x=18446744073709551615");
    expr("reals with exponents", "g : REAL := 1.5E-3; r : LREAL := -1.0e+10; y : REAL := REAL#3; ag : LREAL := 1_000.5;", "",
         "g=0.0015; r=-10000000000.0; y=3.0; ag=1000.5");
    expr("durations", "h : TIME := T#1h2m3.5s; i : TIME := T#-5s; u : TIME := TIME#100ms; v : TIME := t#1.5s; ad : TIME := T#25h; ae : TIME := T#0.5ms;", "",
         "h=T#1h2m3s500ms; i=T#-5s; u=T#100ms; v=T#1s500ms; ad=T#1d1h; ae=T#500us");
    expr("long durations", "j : LTIME := LT#1d2h; k : LTIME := LTIME#5ms;", "", "j=LT#1d2h; k=LT#5ms");
    expr("dates and times of day", "k : DATE := D#2024-02-29; l : TOD := TOD#12:30:15.5; m : TIME_OF_DAY := TIME_OF_DAY#23:59:59;", "",
         "k=D#2024-02-29; l=TOD#12:30:15.5; m=TOD#23:59:59");
    expr("dates and times", "n : DT := DT#2024-01-31-12:30:00; o : DATE_AND_TIME := DATE_AND_TIME#1970-01-01-00:00:01;", "",
         "n=DT#2024-01-31-12:30:00; o=DT#1970-01-01-00:00:01");
    expr("string escapes", "p : STRING := 'it$'s $$ $L$N$R$T$0A end'; n : INT;", "n := LEN(p);", "p='it$'s $$ $N$N$R$T$N end'; n=16");
    expr("wide string escapes", "q : WSTRING := \"w$0041$\"x\"; n : INT;", "n := LEN(q);", "q=\"wA$\"x\"; n=4");
    // A CHAR literal is a one-character string ('A'), with or without the CHAR# prefix.
    expr("char literals", "c : CHAR := 'A'; d : CHAR := CHAR#'b'; w : WCHAR := \"z\"; e : CHAR;", "e := '$N';", "c='A'; d='b'; w=\"z\"; e='$N'");
    expr("comments and pragmas", "x : INT;", "(* a (* nested *) comment *) // to the end\n{ pragma }\nx := 1; (* x := 2; *)", "x=1");
    expr("located variables", "q AT %QX0.1 : BOOL; w AT %QW3 : WORD; m AT %MD10 : DINT;", "q := TRUE; w := 16#1234; m := -5;",
         "%QX0.1=TRUE; %QW3=4660; m=-5; %MD10=4294967291");
}

void TestStdlibAudit::standardFunctions_data()
{
    columns();
    expr("numeric", "a : INT; b : REAL; c : LREAL; d : REAL; e : REAL; f : REAL;",
         "a := ABS(-5); b := ABS(-2.5); c := SQRT(LREAL#16.0); d := LN(1.0); e := LOG(100.0); f := EXP(0.0);",
         "a=5; b=2.5; c=4.0; d=0.0; e=2.0; f=1.0");
    expr("ABS of the smallest INT wraps", "a : INT := -32768;", "a := ABS(a);", "a=-32768");
    expr("trigonometry", "s : REAL; c : REAL; t : REAL; as : REAL; ac : REAL; a4 : REAL;",
         "s := SIN(0.0); c := COS(0.0); t := TAN(0.0); as := ASIN(1.0) * 2.0; ac := ACOS(1.0); a4 := ATAN(1.0) * 4.0;",
         "s=0.0; c=1.0; t=0.0; as=3.1415927; ac=0.0; a4=3.1415927");
    expr("EXPT", "a : REAL; b : LREAL; c : REAL;", "a := EXPT(2.0, 3); b := EXPT(LREAL#2.0, -1); c := EXPT(REAL#10.0, REAL#2.0);",
         "a=8.0; b=0.5; c=100.0");
    expr("TRUNC", "a : DINT; b : DINT;", "a := TRUNC(2.7); b := TRUNC(-2.7);", "a=2; b=-2");
    expr("extensible arithmetic", "a : INT; m : INT; s : INT; d : INT; e : INT; r : INT; q : INT; v : INT;",
         "a := ADD(1, 2, 3, 4); m := MUL(2, 3, 4); s := SUB(10, 3); d := DIV(7, 2); e := DIV(-7, 2); r := MOD(7, 3); q := MOD(-7, 3); v := MOVE(42);",
         "a=10; m=24; s=7; d=3; e=-3; r=1; q=-1; v=42");
    expr("shifts and rotations", "a : BYTE; b : BYTE; c : BYTE; d : BYTE; e : WORD; f : DWORD;",
         "a := SHL(BYTE#16#81, 1); b := SHR(BYTE#16#81, 1); c := ROL(BYTE#16#81, 1); d := ROR(BYTE#16#81, 1); e := ROL(WORD#16#8001, 4); f := ROR(DWORD#1, 1);",
         "a=2; b=64; c=3; d=192; e=24; f=2147483648");
    // A literal shifted: SHL(1, 3) is the literal 8; with a count known only at run time the
    // literal takes the width of the variable assigned (it was a DWORD: "cannot be used as WORD").
    expr("shifting literals", "w : WORD; b : BYTE; c : BYTE; n : INT := 3; d : DWORD; e : LWORD; f : BYTE := 1;",
         "w := SHL(1, n); b := ROL(16#81, 1); d := SHR(16#FF, 4); c := SHL(1, 3) OR f; e := SHL(1, 40);",
         "w=8; b=3; d=15; c=9; e=1099511627776");
    expr("extensible logic", "a : BYTE; o : BYTE; x : BYTE; n : BYTE; b : BOOL; c : BOOL;",
         "a := AND(BYTE#16#FF, BYTE#16#0F, BYTE#16#3C); o := OR(BYTE#1, BYTE#2, BYTE#4); x := XOR(BYTE#16#FF, BYTE#16#0F, BYTE#16#01); n := NOT BYTE#16#0F;"
         "b := AND(TRUE, TRUE, FALSE); c := OR(FALSE, FALSE, TRUE);",
         "a=12; o=7; x=241; n=240; b=FALSE; c=TRUE");
    expr("selection", "s : INT; mx : INT; mn : INT; l : INT; m : INT; k : INT := 3; g : BOOL;",
         "s := SEL(g, 1, 2); mx := MAX(3, 9, 4); mn := MIN(3, 9, -4); l := LIMIT(0, 15, 10); m := MUX(k, 10, 20, 30, 40);",
         "s=1; mx=9; mn=-4; l=10; m=40");
    // Literals in MAX, MIN, LIMIT, SEL and MUX stay literals (they were INT: "INT cannot be used as SINT").
    expr("selection of literals", "s : SINT; u : USINT; w : WORD; l : SINT; k : INT := 1; r : REAL; b : BYTE; m : SINT := -3; q : SINT;",
         "s := MAX(1, 2); u := SEL(TRUE, 1, 2); w := MUX(k, 1, 2, 3); l := LIMIT(0, 15, 10); r := MIN(1, 2.5); b := MUX(k, 16#F0, 16#0F); q := MAX(m, 5);",
         "s=2; u=2; w=2; l=10; r=1.0; b=15; q=5");
    expr("extensible comparisons", "a : BOOL; b : BOOL; c : BOOL; d : BOOL; e : BOOL; f : BOOL; g : BOOL;",
         "a := GT(3, 2, 1); b := GT(3, 2, 2); c := GE(3, 3, 2); d := EQ(2, 2, 2); e := NE(1, 2); f := LT(1, 2, 3); g := LE(1, 1, 0);",
         "a=TRUE; b=FALSE; c=TRUE; d=TRUE; e=TRUE; f=TRUE; g=FALSE");
    expr("integer wraparound", "a : SINT := 127; b : USINT; c : UINT; d : DINT := 2147483647; e : UDINT; f : LINT := 9223372036854775807; g : ULINT; h : INT := 200;",
         "a := a + 1; b := b - 1; c := c - 1; d := d + 1; e := e - 1; f := f + 1; g := g - 1; h := h * 200;",
         "a=-128; b=255; c=65535; d=-2147483648; e=4294967295; f=-9223372036854775808; g=18446744073709551615; h=-25536");
    expr("strings", "s : STRING := 'Hello World'; l : INT; a : STRING; b : STRING; c : STRING; d : STRING; e : STRING; f : STRING; g : STRING; i : INT; j : INT;",
         "l := LEN(s); a := LEFT(s, 5); b := RIGHT(s, 5); c := MID(s, 3, 2); d := CONCAT('a', 'b', 'c', 'd'); e := INSERT('abc', 'XY', 2);"
         "f := DELETE('abcdef', 2, 3); g := REPLACE('abcdef', 'XY', 3, 2); i := FIND(s, 'World'); j := FIND(s, 'xyz');",
         "l=11; a='Hello'; b='World'; c='ell'; d='abcd'; e='abXYc'; f='abef'; g='aXYef'; i=7; j=0");
    expr("time functions", "a : TIME; b : TIME; c : TOD; d : DT; e : TIME; f : TIME; g : DT; h : TIME; i : TIME;",
         "a := ADD_TIME(T#1s, T#500ms); b := SUB_TIME(T#1s, T#1500ms); c := ADD_TOD_TIME(TOD#10:00:00, T#2h30m); d := ADD_DT_TIME(DT#2024-12-31-23:00:00, T#1h);"
         "e := SUB_DT_DT(DT#2024-01-02-00:00:00, DT#2024-01-01-12:00:00); f := SUB_DATE_DATE(D#2024-03-01, D#2024-02-28);"
         "g := CONCAT_DATE_TOD(D#2024-01-01, TOD#10:20:30); h := MUL_TIME(T#1s, 3); i := DIV_TIME(T#1s, 4);",
         "a=T#1s500ms; b=T#-500ms; c=TOD#12:30:00; d=DT#2025-01-01-00:00:00; e=T#12h; f=T#2d; g=DT#2024-01-01-10:20:30; h=T#3s; i=T#250ms");
    expr("time operators", "a : TIME; b : TIME; c : TOD; d : TIME; e : TIME; f : BOOL; g : TIME;",
         "a := T#1s + T#2s; b := T#1s - T#3s; c := TOD#12:00:00 + T#30m; d := T#1s * 2; e := T#3s / 2; f := T#1s > T#999ms; g := TOD#12:00:00 - TOD#11:00:00;",
         "a=T#3s; b=T#-2s; c=TOD#12:30:00; d=T#2s; e=T#1s500ms; f=TRUE; g=T#1h");
}

void TestStdlibAudit::conversions_data()
{
    columns();
    // REAL_TO_INT rounds half away from zero, as CODESYS V2.3 does (IEC says "round").
    expr("rounding", "a : INT; b : INT; c : INT; d : INT; e : DINT; f : INT; g : INT;",
         "a := REAL_TO_INT(2.5); b := REAL_TO_INT(-2.5); c := REAL_TO_INT(3.5); d := REAL_TO_INT(2.4999); e := LREAL_TO_DINT(-0.5); f := REAL_TO_INT(0.5); g := REAL_TO_INT(-0.5);",
         "a=3; b=-3; c=4; d=2; e=-1; f=1; g=-1");
    expr("rounding at run time", "r : REAL := 2.5; n : REAL := -2.5; a : INT; b : INT; t : DINT;",
         "a := REAL_TO_INT(r); b := REAL_TO_INT(n); t := TRUNC(n);", "a=3; b=-3; t=-2");
    expr("narrowing wraps", "a : SINT; b : USINT; c : BYTE; d : UDINT; e : LINT; f : INT;",
         "a := INT_TO_SINT(300); b := INT_TO_USINT(-1); c := INT_TO_BYTE(-1); d := DINT_TO_UDINT(-1); e := ULINT_TO_LINT(ULINT#18446744073709551615); f := BYTE_TO_INT(BYTE#16#FF);",
         "a=44; b=255; c=255; d=4294967295; e=-1; f=255");
    expr("to and from BOOL", "a : BOOL; b : BOOL; c : INT;", "a := INT_TO_BOOL(5); b := REAL_TO_BOOL(0.0); c := BOOL_TO_INT(TRUE);",
         "a=TRUE; b=FALSE; c=1");
    expr("to and from STRING", "a : STRING; b : STRING; c : STRING; d : INT; e : REAL; f : STRING; g : BOOL; h : STRING;",
         "a := INT_TO_STRING(-42); b := REAL_TO_STRING(1.5); c := BOOL_TO_STRING(TRUE); d := STRING_TO_INT('123'); e := STRING_TO_REAL('2.5');"
         "f := TIME_TO_STRING(T#1m30s); g := STRING_TO_BOOL('TRUE'); h := SINT_TO_STRING(SINT#-5);",
         "a='-42'; b='1.5'; c='TRUE'; d=123; e=2.5; f='T#1m30s'; g=TRUE; h='-5'");
    expr("times as numbers", "a : TIME; b : DINT; c : DATE; d : TOD;",
         "a := DINT_TO_TIME(1500); b := TIME_TO_DINT(T#2s); c := DT_TO_DATE(DT#2024-01-02-03:04:05); d := DT_TO_TOD(DT#2024-01-02-03:04:05);",
         "a=T#1s500ms; b=2000; c=D#2024-01-02; d=TOD#03:04:05");
    // INT_TO_BCD is CODESYS Util's: two digits in a BYTE, 255 for a value outside 0..99 (1234).
    expr("BCD of integers", "a : WORD; b : INT; c : DWORD; d : WORD; e : INT; f : USINT;",
         "a := INT_TO_BCD(1234); b := WORD_BCD_TO_INT(WORD#16#1234); c := DINT_TO_BCD(12345678); d := INT_TO_BCD_WORD(99); e := WORD_BCD_TO_INT(WORD#16#0099); f := BYTE_BCD_TO_USINT(BYTE#16#12);",
         "a=255; b=1234; c=305419896; d=153; e=99; f=12");
    // Generic BCD_TO_INT (any bit string in) and WORD_TO_BCD (a bit string's binary value as BCD).
    expr("generic BCD names", "w : WORD := 16#1234; a : INT; b : DINT; c : WORD; d : BYTE; e : INT;",
         "a := BCD_TO_INT(w); b := BCD_TO_DINT(DWORD#16#00987654); c := WORD_TO_BCD(WORD#99); d := BYTE_TO_BCD(BYTE#42); e := BCD_TO_INT(16#0042);",
         "a=1234; b=987654; c=153; d=66; e=42");
    expr("CHAR and STRING", "c : CHAR := 'A'; s : STRING; t : STRING; n : INT; w : WCHAR := \"z\"; ws : WSTRING;",
         "s := CHAR_TO_STRING(c); t := CONCAT(CHAR_TO_STRING(CHAR#'x'), s); n := CHAR_TO_INT(c); ws := WCHAR_TO_WSTRING(w); ws := CONCAT(ws, CHAR_TO_WSTRING(c));",
         "s='A'; t='xA'; n=65; ws=\"zA\"");
    // STRING_TO_CHAR takes the first character (it read the text as a number: '65' gave 'A').
    expr("STRING to CHAR", "a : CHAR; b : CHAR := 'q'; c : WCHAR; d : CHAR; e : STRING := ''; f : WCHAR;",
         "a := STRING_TO_CHAR('65'); b := STRING_TO_CHAR(e); c := WSTRING_TO_WCHAR(\"xy\"); d := WSTRING_TO_CHAR(\"z\"); f := STRING_TO_WCHAR('w');",
         "a='6'; b='$00'; c=\"x\"; d='z'; f=\"w\"");
}

void TestStdlibAudit::functionBlocks_data()
{
    columns();
    // IEC 61131-3 ed. 3 names the INT counters CTU_INT, CTD_INT, CTUD_INT as well as CTU...
    row("typed counters", "VAR c : CTU_INT; d : CTD_INT; u : CTUD_INT; x : BOOL; END_VAR\n"
                          "c(CU := x, PV := 2); d(CD := x, LD := FALSE, PV := 0); u(CU := x, PV := 1);",
        {"x=TRUE => c.CV=1; c.Q=FALSE; d.CV=-1; d.Q=TRUE; u.CV=1; u.QU=TRUE", "x=FALSE => c.CV=1",
         "x=TRUE => c.CV=2; c.Q=TRUE; d.CV=-2; u.CV=2"});
    row("other typed counters", "VAR a : CTU_DINT; b : CTU_UDINT; c : CTU_LINT; d : CTU_ULINT; e : CTD_UDINT; x : BOOL; END_VAR\n"
                                "a(CU := x, PV := 1); b(CU := x, PV := 1); c(CU := x, PV := 1); d(CU := x, PV := 1); e(CD := x, LD := NOT x, PV := 1);",
        {"x=FALSE => e.CV=1", "x=TRUE => a.CV=1; b.CV=1; c.CV=1; d.CV=1; e.CV=0; e.Q=TRUE", "x=FALSE => e.CV=1",
         "x=TRUE => a.CV=2; d.CV=2; e.CV=0"});
    // CTUD counts rising edges: CD's edge counts down while CU stays TRUE (it did not, when the
    // counter compared the levels of CU and CD); edges on both in one call cancel.
    row("CTUD counts edges, not levels", "VAR c : CTUD; u : BOOL; d : BOOL; END_VAR\nc(CU := u, CD := d, PV := 5);",
        {"u=TRUE => c.CV=1", "d=TRUE => c.CV=0", "u=FALSE; d=FALSE => c.CV=0", "u=TRUE; d=TRUE => c.CV=0; c.QD=TRUE",
         "u=FALSE => c.CV=0", "u=TRUE => c.CV=1"});
    row("CTUD reset and load", "VAR c : CTUD; u : BOOL; r : BOOL; l : BOOL; END_VAR\nc(CU := u, R := r, LD := l, PV := 3);",
        {"l=TRUE => c.CV=3; c.QU=TRUE", "l=FALSE; u=TRUE => c.CV=4", "r=TRUE; l=TRUE => c.CV=0; c.QD=TRUE; c.QU=FALSE"});
    // TON at a 10 ms cycle with PT = T#100ms: Q in the 11th call (ET = 100 ms), never in the first.
    row("TON scan by scan", "VAR t : TON; i : BOOL; END_VAR\nt(IN := i, PT := T#30ms);",
        {"i=TRUE => t.Q=FALSE; t.ET=T#0s", "=> t.ET=T#10ms", "=> t.ET=T#20ms; t.Q=FALSE", "=> t.ET=T#30ms; t.Q=TRUE",
         "=> t.ET=T#30ms; t.Q=TRUE", "i=FALSE => t.Q=FALSE; t.ET=T#0s"});
    row("TOF scan by scan", "VAR t : TOF; i : BOOL; END_VAR\nt(IN := i, PT := T#20ms);",
        {"i=TRUE => t.Q=TRUE; t.ET=T#0s", "i=FALSE => t.Q=TRUE; t.ET=T#0s", "=> t.Q=TRUE; t.ET=T#10ms", "=> t.Q=FALSE; t.ET=T#20ms",
         "i=TRUE => t.Q=TRUE; t.ET=T#0s"});
    row("TP scan by scan", "VAR t : TP; i : BOOL; END_VAR\nt(IN := i, PT := T#20ms);",
        {"i=TRUE => t.Q=TRUE; t.ET=T#0s", "i=FALSE => t.Q=TRUE; t.ET=T#10ms", "i=TRUE => t.Q=FALSE; t.ET=T#20ms",
         "=> t.Q=FALSE; t.ET=T#20ms", "i=FALSE => t.Q=FALSE; t.ET=T#0s", "i=TRUE => t.Q=TRUE"});
    // The input names of CODESYS V2.3, which the editors propose, work beside the IEC ones.
    row("CODESYS input names", "VAR s : SR; r : RS; u : CTU; d : CTD; ud : CTUD; a : BOOL; b : BOOL; END_VAR\n"
                               "s(SET1 := a, RESET := b); r(SET := a, RESET1 := b); u(CU := a, RESET := b, PV := 2);"
                               "d(CD := a, LOAD := b, PV := 2); ud(CU := a, RESET := b AND NOT a, LOAD := b AND a, PV := 7);",
        {"b=TRUE => s.Q1=FALSE; r.Q1=FALSE; u.CV=0; d.CV=2; ud.CV=0", "b=FALSE; a=TRUE => s.Q1=TRUE; r.Q1=TRUE; u.CV=1; d.CV=1; ud.CV=1",
         "a=FALSE; b=TRUE => s.Q1=FALSE; r.Q1=FALSE; u.CV=0; d.CV=2; ud.CV=0", "a=TRUE => s.Q1=TRUE; r.Q1=FALSE; u.CV=0; d.CV=2; ud.CV=7"});
    row("bistables and edges", "VAR s : SR; r : RS; rt : R_TRIG; ft : F_TRIG; a : BOOL; b : BOOL; END_VAR\n"
                               "s(S1 := a, R := b); r(S := a, R1 := b); rt(CLK := a); ft(CLK := a);",
        {"=> s.Q1=FALSE; r.Q1=FALSE; rt.Q=FALSE; ft.Q=FALSE", "a=TRUE; b=TRUE => s.Q1=TRUE; r.Q1=FALSE; rt.Q=TRUE",
         "b=FALSE => s.Q1=TRUE; r.Q1=TRUE; rt.Q=FALSE", "a=FALSE => ft.Q=TRUE; s.Q1=TRUE", "b=TRUE => s.Q1=FALSE; r.Q1=FALSE; ft.Q=FALSE"});
}

void TestStdlibAudit::realsPrintAsFloats_data()
{
    QTest::addColumn<QString>("declaration");
    QTest::addColumn<QString>("value");
    // A REAL prints as the shortest text that reads back to the same float, not as the double
    // the float widens to (0.10000000149011612).
    QTest::newRow("tenth") << "r : REAL := 0.1;" << "0.1";
    QTest::newRow("third") << "r : REAL := 1.0 / 3.0;" << "0.33333334";
    QTest::newRow("pi") << "r : REAL := 3.14159265358979;" << "3.1415927";
    QTest::newRow("large") << "r : REAL := 1.0E20;" << "1e+20";
    // Plain digits up to 1e16 come from the shortest digits, not the float's exact 999999986991104.
    QTest::newRow("1e15 in plain digits") << "r : REAL := 1.0E15;" << "1000000000000000.0";
    QTest::newRow("small in plain digits") << "r : REAL := -1.5E-5;" << "-0.000015";
    QTest::newRow("int above 2^24") << "r : REAL := 123456789.0;" << "123456792.0";
    QTest::newRow("LREAL keeps its digits") << "r : LREAL := 0.1;" << "0.1";
    QTest::newRow("REAL widened to LREAL") << "r : LREAL := REAL_TO_LREAL(0.1);" << "0.10000000149011612";
}

void TestStdlibAudit::realsPrintAsFloats()
{
    QFETCH(QString, declaration);
    QFETCH(QString, value);
    QCOMPARE(runTrace(QStringLiteral("VAR ") + declaration + QStringLiteral(" END_VAR\n"), {QStringLiteral("=> r=") + value}), QString());
    QCOMPARE(formatReal(0.1f), QStringLiteral("0.1"));
    QCOMPARE(formatReal(100.0f), QStringLiteral("100.0"));
}

void TestStdlibAudit::wrongCharLiteral()
{
    Diagnostics diagnostics;
    QVERIFY(!compileText(QStringLiteral("PROGRAM Main\nVAR c : CHAR := 'AB'; END_VAR\nEND_PROGRAM\n"), diagnostics));
    QCOMPARE(errorsOf(diagnostics), QStringLiteral("Main:2:17: error: A CHAR holds exactly one character, not 2."));
}

void TestStdlibAudit::writesOfEnumsAndChars_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("literal");
    QTest::addColumn<QString>("problem"); // empty: accepted
    QTest::addColumn<QString>("value");   // read back
    // --set and the watch pane write what --watch prints: Color#Blue, an anonymous enum's value, 'A'.
    QTest::newRow("qualified enum") << "c" << "Color#Blue" << "" << "Color#Blue";
    QTest::newRow("bare enum value") << "c" << "green" << "" << "Color#Green";
    QTest::newRow("enum by number") << "c" << "0" << "" << "Color#Red";
    QTest::newRow("unknown enum value") << "c" << "Purple" << "'Purple' is not a valid Color." << "Color#Red";
    QTest::newRow("enum of another type") << "c" << "Mode#Blue" << "'Mode#Blue' is not a valid Color." << "Color#Red";
    QTest::newRow("anonymous enum") << "a" << "Fast" << "" << "Fast";
    QTest::newRow("char") << "ch" << "'z'" << "" << "'z'";
    QTest::newRow("char escape") << "ch" << "'$''" << "" << "'$''";
    QTest::newRow("char too long") << "ch" << "'ab'" << "''ab'' is not a valid CHAR." << "'x'";
    QTest::newRow("char by code") << "ch" << "65" << "" << "'A'";
    QTest::newRow("wchar") << "wc" << "\"q\"" << "" << "\"q\"";
}

void TestStdlibAudit::writesOfEnumsAndChars()
{
    QFETCH(QString, name);
    QFETCH(QString, literal);
    QFETCH(QString, problem);
    QFETCH(QString, value);
    Diagnostics diagnostics;
    const auto module = compileText(QStringLiteral("TYPE Color : (Red, Green, Blue); END_TYPE\n"
                                                   "PROGRAM Main VAR c : Color; a : (Slow, Fast); ch : CHAR := 'x'; wc : WCHAR; END_VAR\nEND_PROGRAM\n"),
                                    diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    QCOMPARE(runtime.write(QStringLiteral("Main.") + name, literal).value_or(QString()), problem);
    QCOMPARE(runtime.read(QStringLiteral("Main.") + name).value_or(QString()), value);
}

void TestStdlibAudit::inputVariablesAreWrittenInTheImage()
{
    // A variable AT %I is copied from the input image at the start of each cycle: a write to it
    // by name (--set Main.start=TRUE, the watch pane) went to the copy and was overwritten.
    QCOMPARE(runTrace(QStringLiteral("VAR start AT %IX0.3 : BOOL; level AT %IW2 : INT; lamp AT %QX0.0 : BOOL; twice : INT; END_VAR\n"
                                     "lamp := start; twice := level * 2;"),
                      {QStringLiteral("start=TRUE; level=-21 => lamp=TRUE; twice=-42; %IX0.3=TRUE; %IW2=65515; start=TRUE; level=-21"),
                       QStringLiteral("%IX0.3=FALSE => lamp=FALSE; start=FALSE; level=-21")}),
             QString());
}

QTEST_GUILESS_MAIN(TestStdlibAudit)
#include "tst_stdlib_audit.moc"
