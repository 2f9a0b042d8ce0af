// The CODESYS dialect of IEC 61131-3, scan by scan with the values CODESYS computes:
// implicit conversions (accepted with CODESYS's warnings, the value wraps or is rounded like
// the *_TO_* function), pointers and references, AND_THEN/OR_ELSE, CONTINUE and JMP in ST.
#include "tracerunner.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;
using namespace iec::interp::testing::table;

namespace {

// The warnings of a program as "line:column: message", joined by " | "; "does not compile: ..."
// when it has errors.
QString warningsOf(const QString &body, const QString &declarations)
{
    Diagnostics diagnostics;
    compileText(QStringLiteral("PROGRAM Main\nVAR %1 END_VAR\n%2\nEND_PROGRAM\n").arg(declarations, body), diagnostics);
    if (diagnostics.hasErrors())
        return QStringLiteral("does not compile: ") + errorsOf(diagnostics);
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << QStringLiteral("%1:%2: %3").arg(d.location.line).arg(d.location.column).arg(d.message);
    return lines.join(QStringLiteral(" | "));
}

} // namespace

class TestDialect : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void implicitConversions_data();
    void implicitConversions() { check(); }
    void conversionWarnings_data();
    void conversionWarnings();
    void pragmaMessagesNameTheirPou();
    void pointers_data();
    void pointers() { check(); }
    void pointerFaults_data();
    void pointerFaults();
    void references_data();
    void references() { check(); }
    void oscatForms_data();
    void oscatForms() { check(); }
    void controlFlow_data();
    void controlFlow() { check(); }
};

void TestDialect::implicitConversions_data()
{
    columns();
    // DINT 70000 = 16#1_1170 into an INT keeps 16#1170 = 4464 (CODESYS on x86: the low word).
    expr("narrowing wraps", "i : INT; d : DINT := 70000;", "i := d;", "i=4464");
    expr("signed to unsigned", "u : UINT; i : INT := -1;", "u := i;", "u=65535");
    expr("word to int", "i : INT; w : WORD := 16#FFFF;", "i := w;", "i=-1");
    expr("byte to sint", "s : SINT; b : BYTE := 200;", "s := b;", "s=-56");
    // REAL to an integer rounds as REAL_TO_INT does: 2.5 -> 3, -2.5 -> -3, 1.4 -> 1.
    expr("real to int rounds", "i : INT; j : INT; k : INT; r : REAL := 2.5; q : REAL := -2.5; t : REAL := 1.4;", "i := r; j := q; k := t;", "i=3; j=-3; k=1");
    expr("lreal to real", "r : REAL; l : LREAL := 0.1;", "r := l;", "r=0.1");
    expr("dint to real", "r : REAL; d : DINT := 16777217;", "r := d;", "r=16777216.0");
    // TRUNC gives the integer type it is assigned to (no warning), cutting towards zero.
    expr("trunc into int", "i : INT; r : REAL := -2.7; s : SINT; q : REAL := 99.9;", "i := TRUNC(r); s := TRUNC(q);", "i=-2; s=99");
    // CODESYS computes with bit strings and combines integers bit by bit.
    expr("word arithmetic", "w : WORD := 16#00FF; b : BYTE := 255;", "w := w + 1; b := b + 1;", "w=256; b=0");
    expr("integer and", "i : INT := -1; x : INT;", "x := i AND 16#0F0F;", "x=3855");
    expr("not of an integer", "i : INT := 5; x : INT;", "x := NOT i;", "x=-6");
    expr("word and int", "w : WORD := 16#8000; i : INT := 1; d : DINT;", "d := w + i;", "d=32769");
    expr("function argument narrowed", "s : SINT; i : INT := 300;", "s := MAX(i, 0);", "s=44");
}

void TestDialect::conversionWarnings_data()
{
    QTest::addColumn<QString>("declarations");
    QTest::addColumn<QString>("body");
    QTest::addColumn<QString>("warnings");
    QTest::newRow("narrowing") << "i : INT; d : DINT;" << "i := d;" << "3:1: Implicit conversion from DINT to INT: possible loss of information.";
    QTest::newRow("sign") << "u : UINT; i : INT;" << "u := i;" << "3:1: Implicit conversion from signed type INT to unsigned type UINT: possible change of sign.";
    QTest::newRow("unsigned to signed") << "u : UINT; i : INT;" << "i := u;" << "3:1: Implicit conversion from unsigned type UINT to signed type INT: possible change of sign.";
    QTest::newRow("real to int") << "r : REAL; i : INT;" << "i := r;" << "3:1: Implicit conversion from REAL to INT: possible loss of information.";
    QTest::newRow("word to uint is silent") << "u : UINT; w : WORD;" << "u := w; w := u;" << "";
    QTest::newRow("widening is silent") << "i : INT; d : DINT; r : LREAL;" << "d := i; r := d;" << "";
    QTest::newRow("trunc is silent") << "i : INT; r : REAL;" << "i := TRUNC(r);" << "";
    QTest::newRow("literals are silent") << "b : BYTE; s : SINT;" << "b := 255; s := -128;" << "";
    // Pragmas: the attributes CODESYS writes are kept without a word, {warning} is shown, an
    // unknown one gets a note.
    QTest::newRow("attribute pragma") << "i : INT;" << "{attribute 'qualified_only'}\ni := 1;" << "";
    QTest::newRow("warning pragma") << "i : INT;" << "{warning 'calibrate first'}\ni := 1;" << "3:1: calibrate first";
    QTest::newRow("unknown pragma") << "i : INT;" << "{frobnicate 7}\ni := 1;"
                                    << "3:1: The pragma {frobnicate 7} means nothing to IEC Studio; it is ignored.";
}

void TestDialect::conversionWarnings()
{
    QFETCH(QString, declarations);
    QFETCH(QString, body);
    QFETCH(QString, warnings);
    QCOMPARE(warningsOf(body, declarations), warnings);
}

void TestDialect::pragmaMessagesNameTheirPou()
{
    // In a text of several POUs a pragma's message names the POU it stands in; an attribute
    // before a POU's keyword belongs to that POU (CODESYS writes them there).
    Diagnostics diagnostics;
    compileText(QStringLiteral("{frobnicate 1}\n"
                               "FUNCTION_BLOCK Fb\nVAR_INPUT x : INT; END_VAR\n{warning 'in Fb'}\nx := x + 1;\nEND_FUNCTION_BLOCK\n"
                               "{warning 'before Main'}\n"
                               "PROGRAM Main\nVAR f : Fb; END_VAR\n{warning 'in Main'}\nf(x := 1);\nEND_PROGRAM\n"),
        diagnostics);
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << QStringLiteral("%1:%2: %3").arg(d.pou).arg(d.location.line).arg(d.message);
    QCOMPARE(lines.join(QStringLiteral(" | ")),
        QStringLiteral("Fb:1: The pragma {frobnicate 1} means nothing to IEC Studio; it is ignored. | Fb:4: in Fb"
                       " | Main:7: before Main | Main:10: in Main"));
}

void TestDialect::pointers_data()
{
    columns();
    expr("read and write through a pointer", "p : POINTER TO INT; x : INT := 5; y : INT;", "p := ADR(x); y := p^; p^ := 7;", "x=7; y=5");
    // Pointer arithmetic counts bytes: two INTs further is 4 bytes further.
    expr("arithmetic in bytes", "arr : ARRAY[0..3] OF INT := [10, 20, 30, 40]; p : POINTER TO INT; y : INT;",
         "p := ADR(arr[0]); p := p + 2 * SIZEOF(arr[0]); y := p^;", "y=30");
    expr("sizeof", "d : DINT; arr : ARRAY[1..5] OF LREAL; s1 : DINT; s2 : DINT; s3 : DINT; s4 : DINT;",
         "s1 := SIZEOF(d); s2 := SIZEOF(arr); s3 := SIZEOF(INT); s4 := SIZEOF(arr[2]);", "s1=4; s2=40; s3=2; s4=8");
    // x86 stores the low byte first: DWORD 16#11223344 is 44 33 22 11 in memory.
    expr("bytes of a dword", "d : DWORD := 16#11223344; pb : POINTER TO BYTE; b0 : BYTE; b1 : BYTE;",
         "pb := ADR(d); b0 := pb^; pb := pb + 1; b1 := pb^;", "b0=68; b1=51");
    expr("compare with 0", "p : POINTER TO INT; x : INT; none : BOOL; set : BOOL;", "none := p = 0; p := ADR(x); set := p <> 0;", "none=TRUE; set=TRUE");
    expr("distance of two pointers", "arr : ARRAY[0..9] OF DINT; a : POINTER TO DINT; b : POINTER TO DINT; n : DINT;",
         "a := ADR(arr[2]); b := ADR(arr[7]); n := b - a;", "n=20");
    // An element through a pointer to an array: p^[i].
    expr("element through a pointer to an array", "arr : ARRAY[1..4] OF INT := [1, 2, 3, 4]; p : POINTER TO ARRAY[1..4] OF INT; i : INT := 3; y : INT;",
         "p := ADR(arr); y := p^[i]; p^[2] := 20;", "y=3; arr[2]=20");
    row("member through a pointer", "TYPE Pair : STRUCT a : INT; b : INT; END_STRUCT; END_TYPE\n"
                                    "PROGRAM Main VAR s : Pair; p : POINTER TO Pair; y : INT; END_VAR\n"
                                    "p := ADR(s); p^.b := 9; y := p^.b + s.b;\nEND_PROGRAM",
        {"=> y=18"});
    // A timer called through a pointer: Q after 20 ms at a 10 ms cycle (its third call).
    row("function block through a pointer", "VAR t : TON; pt : POINTER TO TON; q : BOOL; END_VAR\n"
                                            "pt := ADR(t); pt^(IN := TRUE, PT := T#20ms); q := pt^.Q;",
        {"=> q=FALSE", "=> q=FALSE", "=> q=TRUE"});
    row("pointer to an element chosen at run time", "VAR arr : ARRAY[1..3] OF INT := [1, 2, 3]; i : INT := 2; p : POINTER TO INT; END_VAR\n"
                                                    "p := ADR(arr[i]); p^ := p^ * 10; i := i + 1;",
        {"=> arr=[1, 20, 3]", "=> arr=[1, 20, 30]"});
    // As in CODESYS, a string's address is that of its first character and the string ends at its
    // first NUL, so OSCAT's string functions work: they walk and build strings through pointers.
    expr("a string's address is its first character", "s : STRING(10) := 'abc'; p : POINTER TO BYTE; b : BYTE; n : INT;",
         "p := ADR(s); b := p^; p^ := 65; n := LEN(s);", "b=97; n=3; s='Abc'");
    expr("a string ends at a NUL written through a pointer", "s : STRING(10) := 'abcdef'; p : POINTER TO BYTE; n : INT;",
         "p := ADR(s) + 2; p^ := 0; n := LEN(s);", "n=2; s='ab'");
    expr("a string built through a pointer", "s : STRING(10); p : POINTER TO BYTE; n : INT;",
         "p := ADR(s); p^ := 72; p := p + 1; p^ := 105; p := p + 1; p^ := 0; n := LEN(s);", "n=2; s='Hi'");
    row("a function result built through its address", "FUNCTION Hex : STRING(2)\nVAR_INPUT b : BYTE; END_VAR\nVAR p : POINTER TO BYTE; END_VAR\n"
                                                       "p := ADR(Hex); p^ := 65 + SHR(b, 4); p := p + 1; p^ := 65 + (b AND 15); p := p + 1; p^ := 0;\n"
                                                       "END_FUNCTION\nPROGRAM Main VAR s : STRING(2); k : BYTE := 7; END_VAR\ns := Hex(16#12);\nEND_PROGRAM",
        {"=> s='BC'; k=7"});
    // A pointer that overwrites a string's capacity and length cannot make it reach past its memory:
    // it still ends at its NUL (this read outside the image before; found with OSCAT's UPPERCASE).
    expr("a string header overwritten through a pointer", "s : STRING(4) := 'ab'; t : STRING(80); p : POINTER TO WORD; n : INT;",
         "p := ADR(s) - 4; p^ := 16#FFFF; p := p + 2; p^ := 16#FFFF; n := LEN(s); t := CONCAT(s, 'c');", "n=2; t='abc'");
    // A reference holds the characters' address too; what it refers to is the whole string.
    expr("a reference to a string", "s : STRING(10) := 'abc'; r : REFERENCE TO STRING(10); p : POINTER TO BYTE; n : INT;",
         "r REF= s; r := CONCAT(r, 'd'); p := ADR(r); n := LEN(r);", "s='abcd'; n=4");
    // A STRING(80) passed to a VAR_IN_OUT STRING(10) is read and written through its first 10
    // characters; its own capacity stays 80.
    row("a longer string through a shorter in-out", "FUNCTION Put : BOOL\nVAR_IN_OUT s : STRING(10); END_VAR\nVAR_INPUT t : STRING(20); END_VAR\n"
                                                    "s := t; Put := TRUE;\nEND_FUNCTION\n"
                                                    "PROGRAM Main VAR long : STRING(80) := 'abcdefghijklmnopqrstuvwxyz'; ok : BOOL; n : INT; END_VAR\n"
                                                    "ok := Put(s := long, t := 'xyz'); n := LEN(long); long := CONCAT(long, '0123456789');\nEND_PROGRAM",
        {"=> long='xyz0123456789'; n=3"});
    expr("a pointer to a string", "s : STRING(10) := 'abc'; t : STRING(10); ps : POINTER TO STRING(10);",
         "ps := ADR(s); t := ps^; ps^ := 'xy';", "s='xy'; t='abc'");
    expr("ref_to of edition 3", "r : REF_TO INT; x : INT := 4; y : INT;", "r := REF(x); y := r^ + 1;", "y=5");
    expr("and_then skips a null pointer", "p : POINTER TO INT; ok : BOOL := TRUE; other : BOOL;", "ok := p <> 0 AND_THEN p^ > 0; other := p = 0 OR_ELSE p^ > 0;",
         "ok=FALSE; other=TRUE");
}

void TestDialect::pointerFaults_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("fault");
    QTest::newRow("null pointer read") << "VAR p : POINTER TO INT; y : INT; END_VAR\ny := 1;\ny := p^;"
                                       << "Main:4: A pointer or reference that points nowhere (0) was used. (cycle 1)";
    QTest::newRow("null pointer write") << "VAR p : POINTER TO DINT; END_VAR\np^ := 1;"
                                        << "Main:3: A pointer or reference that points nowhere (0) was used. (cycle 1)";
    QTest::newRow("wild pointer") << "VAR p : POINTER TO INT; x : INT; END_VAR\np := ADR(x) + 100000000;\nx := p^;"
                                  << "Main:4: A pointer that points outside the program's memory was used. (cycle 1)";
    QTest::newRow("unset reference") << "VAR r : REFERENCE TO INT; y : INT; END_VAR\ny := r;"
                                     << "Main:3: A pointer or reference that points nowhere (0) was used. (cycle 1)";
}

void TestDialect::pointerFaults()
{
    QFETCH(QString, source);
    QFETCH(QString, fault);
    Diagnostics diagnostics;
    const QString program = QStringLiteral("PROGRAM Main\n") + source + QStringLiteral("\nEND_PROGRAM\n");
    const auto module = compileText(program, diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    QVERIFY(!runtime.runCycle());
    QCOMPARE(runtime.fault()->toString(), fault);
    QVERIFY(!runtime.runCycle()); // stopped, the host goes on
}

void TestDialect::references_data()
{
    columns();
    expr("read and write through a reference", "r : REFERENCE TO INT; x : INT := 3; y : INT;", "r REF= x; r := r + 1; y := r * 2;", "x=4; y=8");
    expr("isvalidref", "r : REFERENCE TO INT; x : INT; before : BOOL := TRUE; after : BOOL;",
         "before := __ISVALIDREF(r); r REF= x; after := __ISVALIDREF(r);", "before=FALSE; after=TRUE");
    expr("rebinding", "r : REFERENCE TO INT; a : INT; b : INT;", "r REF= a; r := 1; r REF= b; r := 2;", "a=1; b=2");
    row("reference to a struct member", "TYPE Pair : STRUCT a : INT; b : INT; END_STRUCT; END_TYPE\n"
                                        "PROGRAM Main VAR s : Pair; r : REFERENCE TO INT; END_VAR\nr REF= s.b; r := 5;\nEND_PROGRAM",
        {"=> s=(a := 0, b := 5)"});
}

void TestDialect::oscatForms_data()
{
    columns();
    // SHL/SHR of an integer shift its bits as those of the bit string of its size; SHR keeps the
    // sign (OSCAT's SET_DATE: SHR(month - 4, 1) is -1 for March).
    expr("shifts of integers", "a : INT; b : INT; c : INT; d : SINT; e : UINT; m : INT := 3;",
         "a := SHR(m - 4, 1); b := SHR(INT#-8, 2); c := SHL(INT#3, 14); d := SHR(SINT#-128, 7); e := SHR(UINT#65535, 4);",
         "a=-1; b=-2; c=-16384; d=-1; e=4095");
    expr("a negative literal shifted", "a : INT;", "a := SHR(-8, 2);", "a=-2");
    // A REAL written with more digits than 64 bits hold (OSCAT's PI) is rounded.
    expr("long real literal", "r : LREAL := 3.14159265358979323846264338327950288;", "", "r=3.141592653589793");
    // TIME() is the time since the start, here the virtual clock as the cycle begins.
    row("time function", "VAR t : TIME; END_VAR\nt := TIME();", {"=> t=T#0s", "=> t=T#10ms"});
    // CODESYS writes END_STRUCT END_TYPE without a ';'; the ed.3 long date types are names there.
    row("struct without a semicolon and long date names", "TYPE Cal :\nSTRUCT\n\tLDT : DT;\n\tLDATE : DATE;\n\tLTOD : TOD;\nEND_STRUCT\nEND_TYPE\n"
                                                         "PROGRAM Main VAR c : Cal; d : DATE; END_VAR\nc.LDATE := D#2024-02-03; d := c.LDATE;\nEND_PROGRAM",
        {"=> d=D#2024-02-03"});
    // TwinCAT's T_MaxString and the pointer-sized integers of CODESYS 3.5 and TwinCAT.
    expr("vendor built-in types", "s : T_MaxString; x : __XINT := -5; u : UXINT; w : XWORD; n : INT;",
         "s := 'abc'; n := LEN(s); u := 7; w := 16#FF;", "n=3; x=-5; u=7; w=255");
    // TwinCAT's MAX_STRING_LENGTH (Tc2_System), unless the project declares its own.
    expr("twincat string length constant", "m : UDINT; b : ARRAY[0..MAX_STRING_LENGTH] OF BYTE; n : UDINT;",
         "m := MAX_STRING_LENGTH; n := SIZEOF(b);", "m=255; n=256");
    row("own max string length", "VAR_GLOBAL CONSTANT MAX_STRING_LENGTH : INT := 80; END_VAR\nPROGRAM Main VAR m : INT; END_VAR\nm := MAX_STRING_LENGTH;\nEND_PROGRAM",
        {"=> m=80"});
    // Global constants size arrays and strings, in types and in POUs (OSCAT: STRING(STRING_LENGTH)).
    row("global constants in declarations", "VAR_GLOBAL CONSTANT\nN : INT := 3;\nLEN_S : INT := N * 2;\nEND_VAR\n"
                                            "TYPE Buf : ARRAY[0..N] OF INT; END_TYPE\n"
                                            "FUNCTION F : INT\nVAR_INPUT s : STRING(LEN_S); END_VAR\nF := LEN(s) + SIZEOF(s);\nEND_FUNCTION\n"
                                            "PROGRAM Main\nVAR b : Buf; x : INT; n : INT; END_VAR\nx := F('abc'); n := SIZEOF(b);\nEND_PROGRAM",
        {"=> x=10; n=8"}); // LEN 3 + SIZEOF 7 (6 characters and the NUL, as CODESYS counts)
    // CoDeSys 2.3 writes an array's initial values without brackets.
    expr("array values without brackets", "a : ARRAY[0..5] OF INT := 1, 2, 3(7); b : ARRAY[1..3] OF BOOL := TRUE, FALSE, TRUE; c : INT := MAX(1, 2);",
         "", "a=[1, 2, 7, 7, 7, 0]; b=[TRUE, FALSE, TRUE]; c=2");
    row("array of structures without brackets", "TYPE P : STRUCT x : INT; y : INT; END_STRUCT END_TYPE\n"
                                                "PROGRAM Main VAR a : ARRAY[1..3] OF P := (x := 1, y := 2), (x := 3), 1((y := 9)); p : P := (x := 4); END_VAR\nEND_PROGRAM",
        {"=> a=[(x := 1, y := 2), (x := 3, y := 0), (x := 0, y := 9)]; p=(x := 4, y := 0)"});
    // A STRING holds Windows-1252 (CODESYS's code page): € is one byte.
    expr("euro sign in a string", "s : STRING(10) := 'Öl €'; n : INT;", "n := LEN(s);", "n=4; s='Öl €'");
}

void TestDialect::controlFlow_data()
{
    columns();
    expr("continue", "i : INT; s : INT;", "s := 0; FOR i := 1 TO 10 DO IF i MOD 2 = 0 THEN CONTINUE; END_IF; s := s + i; END_FOR;", "s=25");
    row("jmp in st", "VAR i : INT; END_VAR\ni := 0;\nLoop:\ni := i + 1;\nIF i < 5 THEN\nJMP Loop;\nEND_IF;", {"=> i=5", "=> i=5"});
    row("jmp forward in st", "VAR i : INT; j : INT; END_VAR\ni := i + 1;\nJMP Skip;\nj := 99;\nSkip: j := j + i;", {"=> i=1; j=1", "=> i=2; j=3"});
}

QTEST_GUILESS_MAIN(TestDialect)
#include "tst_dialect.moc"
