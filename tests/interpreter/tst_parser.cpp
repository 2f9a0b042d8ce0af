#include "interpreter/compiler/astdump.h"
#include "interpreter/compiler/parser.h"

#include <QTest>

using namespace iec::interp;

namespace {

QString diagnosticsText(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

QString ilText(const std::vector<ast::IlInstruction> &list)
{
    QStringList parts;
    for (const auto &i : list)
        parts << ast::dump(i);
    return parts.join(QStringLiteral("; "));
}

} // namespace

class TestParser : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void expressions_data();
    void expressions();
    void statements_data();
    void statements();
    void declarations_data();
    void declarations();
    void types();
    void instructionList_data();
    void instructionList();
    void sfc_data();
    void sfc();
    void programUnit();
    void configuration();
    void diagnostics_data();
    void diagnostics();
};

void TestParser::expressions_data()
{
    QTest::addColumn<QString>("expression");
    QTest::addColumn<QString>("tree");
    auto row = [](const char *source, const char *tree) { QTest::newRow(source) << QString::fromUtf8(source) << QString::fromUtf8(tree); };
    row("a + b * c", "(+ a (* b c))");
    row("(a + b) * c", "(* (+ a b) c)");
    row("a - b - c", "(- (- a b) c)");
    row("a ** 2 * b", "(* (** a 2) b)");
    row("a ** b ** c", "(** (** a b) c)");
    row("-a ** 2", "(** (- a) 2)");
    row("-5 + x", "(+ -5 x)");
    row("- 5", "(- 5)");
    row("NOT a AND b", "(AND (NOT a) b)");
    row("a OR b AND c", "(OR a (AND b c))");
    row("a XOR b OR c", "(OR (XOR a b) c)");
    row("a AND b XOR c", "(XOR (AND a b) c)");
    row("a & b", "(AND a b)");
    row("a < b = c > d", "(= (< a b) (> c d))");
    row("a <> b", "(<> a b)");
    row("a + b <= c MOD 3", "(<= (+ a b) (MOD c 3))");
    row("x / y", "(/ x y)");
    row("f(1, 2)", "f(1, 2)");
    row("f()", "f()");
    row("LIMIT(MN := 0, IN := x, MX := 10)", "LIMIT(MN := 0, IN := x, MX := 10)");
    row("ADD(a, b, c)", "ADD(a, b, c)");
    row("INT_TO_REAL(i) * 2.0", "(* INT_TO_REAL(i) 2.0)");
    row("arr[i + 1, 2]", "arr[(+ i 1), 2]");
    row("a.b.c", "a.b.c");
    row("Timer1.Q", "Timer1.Q");
    row("Inst.Sub.Out", "Inst.Sub.Out");
    row("w.3", "w.%3");
    row("pts[2].x", "pts[2].x");
    row("%IX0.1 AND %QX0.2", "(AND %IX0.1 %QX0.2)");
    row("T#1s + TIME#500ms", "(+ T#1s TIME#500ms)");
    row("TRUE OR false", "(OR TRUE FALSE)");
    row("'abc'", "'abc'");
    row("16#FF AND INT#5", "(AND 16#FF INT#5)");
    row("Color#Red", "Color#Red");
    row("S.R", "S.R");
}

void TestParser::expressions()
{
    QFETCH(QString, expression);
    QFETCH(QString, tree);
    Diagnostics diagnostics;
    const QString source = QStringLiteral("x := ") + expression + QLatin1Char(';');
    const auto body = parseStBody(source, QStringLiteral("T"), diagnostics);
    QCOMPARE(diagnosticsText(diagnostics), QString());
    QCOMPARE(body.size(), size_t{1});
    QCOMPARE(ast::dump(body[0].value), tree);
}

void TestParser::statements_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("tree");
    auto row = [](const char *name, const char *source, const char *tree) {
        QTest::newRow(name) << QString::fromUtf8(source) << QString::fromUtf8(tree);
    };
    row("assignment", "a := 1;", "(:= a 1)");
    row("empty", ";", "(empty)");
    row("fb call formal", "T1(IN := x, PT := T#1s);", "(call T1(IN := x, PT := T#1s))");
    row("fb call outputs", "T1(IN := x, Q => q, ET => et);", "(call T1(IN := x, Q => q, ET => et))");
    row("negated output", "R(NOT Q => nq);", "(call R(NOT Q => nq))");
    row("nested instance call", "A.B(x := 1);", "(call A.B(x := 1))");
    row("function call statement", "f(1);", "(call f(1))");
    row("if", "IF a THEN b := 1; END_IF;", "(if a {(:= b 1)})");
    row("if elsif else", "IF a THEN b := 1; ELSIF c THEN b := 2; ELSE b := 3; END_IF",
        "(if a {(:= b 1)} c {(:= b 2)} else {(:= b 3)})");
    row("case", "CASE i OF 1: a := 1; 2, 3: a := 2; 10..20, 30: a := 3; ELSE a := 0; END_CASE",
        "(case i 1: {(:= a 1)} 2,3: {(:= a 2)} 10..20,30: {(:= a 3)} else {(:= a 0)})");
    row("case negative label", "CASE i OF -1: a := 1; END_CASE", "(case i -1: {(:= a 1)})");
    row("case qualified enum labels", "CASE c OF Color.Red: a := 1; END_CASE", "(case c Color.Red: {(:= a 1)})");
    row("case enum labels", "CASE c OF Red, Green: a := 1; Blue: a := 2; END_CASE",
        "(case c Red,Green: {(:= a 1)} Blue: {(:= a 2)})");
    row("for", "FOR i := 1 TO 10 DO s := s + i; END_FOR", "(for i 1 10 {(:= s (+ s i))})");
    row("for by negative", "FOR i := 10 TO 1 BY -2 DO ; END_FOR", "(for i 10 1 by -2 {(empty)})");
    row("while", "WHILE j <= 100 AND arr[j] <> 50 DO j := j + 2; END_WHILE",
        "(while (AND (<= j 100) (<> arr[j] 50)) {(:= j (+ j 2))})");
    row("repeat", "REPEAT j := j + 2; UNTIL j = 51 END_REPEAT;", "(repeat {(:= j (+ j 2))} until (= j 51))");
    row("exit return continue", "EXIT; RETURN; CONTINUE;", "(exit) (return) (continue)");
    row("nested", "IF a THEN FOR i := 1 TO 2 DO IF b THEN EXIT; END_IF; END_FOR; END_IF;",
        "(if a {(for i 1 2 {(if b {(exit)})})})");
    row("address target", "%QX0.1 := %IX0.0;", "(:= %QX0.1 %IX0.0)");
    row("bit target", "w.3 := TRUE;", "(:= w.%3 TRUE)");
    row("index target", "m[i, j] := 0;", "(:= m[i, j] 0)");
    row("il words as names", "R := S; ST := LD;", "(:= R S) (:= ST LD)");
}

void TestParser::statements()
{
    QFETCH(QString, source);
    QFETCH(QString, tree);
    Diagnostics diagnostics;
    const auto body = parseStBody(source, QStringLiteral("T"), diagnostics);
    QCOMPARE(diagnosticsText(diagnostics), QString());
    QCOMPARE(ast::dump(body), tree);
}

void TestParser::declarations_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("tree");
    auto row = [](const char *name, const char *source, const char *tree) {
        QTest::newRow(name) << QString::fromUtf8(source) << QString::fromUtf8(tree);
    };
    row("simple", "VAR a : INT; b, c : BOOL := TRUE; END_VAR", "VAR a:INT; b:BOOL:=TRUE; c:BOOL:=TRUE;");
    row("input output", "VAR_INPUT x : REAL := 1.5; END_VAR", "VAR_INPUT x:REAL:=1.5;");
    row("constant", "VAR CONSTANT N : INT := 10; END_VAR", "VAR CONSTANT N:INT:=10;");
    row("retain", "VAR RETAIN cnt : DINT; END_VAR", "VAR RETAIN cnt:DINT;");
    row("non retain", "VAR_OUTPUT NON_RETAIN q : BOOL; END_VAR", "VAR_OUTPUT NON_RETAIN q:BOOL;");
    row("at", "VAR in1 AT %IX0.0 : BOOL; out AT %QW2 : WORD; END_VAR", "VAR in1 AT %IX0.0:BOOL; out AT %QW2:WORD;");
    row("array", "VAR a : ARRAY[1..10] OF INT; END_VAR", "VAR a:ARRAY[1..10] OF INT;");
    row("array 2d init", "VAR m : ARRAY[0..1, 0..2] OF INT := [1, 2, 3, 4(0)]; END_VAR",
        "VAR m:ARRAY[0..1,0..2] OF INT:=[1,2,3,4(0)];");
    row("array repeat empty", "VAR a : ARRAY[1..3] OF INT := [3()]; END_VAR", "VAR a:ARRAY[1..3] OF INT:=[3()];");
    row("array of struct init", "VAR p : ARRAY[1..2] OF Pt := [(x := 1, y := 2), (x := 3)]; END_VAR",
        "VAR p:ARRAY[1..2] OF Pt:=[(x:=1,y:=2),(x:=3)];");
    row("struct init", "VAR p : Pt := (x := 1, y := -2); END_VAR", "VAR p:Pt:=(x:=1,y:=-2);");
    row("string", "VAR s : STRING[20] := 'hi'; w : WSTRING; t : STRING(5); END_VAR",
        "VAR s:STRING[20]:='hi'; w:WSTRING; t:STRING[5];");
    row("fb instance", "VAR t1 : TON; END_VAR", "VAR t1:TON;");
    row("subrange", "VAR pct : INT(0..100); END_VAR", "VAR pct:INT(0..100);");
    row("in out external temp", "VAR_IN_OUT io : INT; END_VAR VAR_EXTERNAL g : BOOL; END_VAR VAR_TEMP t : LREAL; END_VAR",
        "VAR_IN_OUT io:INT;|VAR_EXTERNAL g:BOOL;|VAR_TEMP t:LREAL;");
    row("parenthesised expression init", "VAR x : INT := (1 + 2) * 3; END_VAR", "VAR x:INT:=(* (+ 1 2) 3);");
}

void TestParser::declarations()
{
    QFETCH(QString, source);
    QFETCH(QString, tree);
    Diagnostics diagnostics;
    const auto sections = parseDeclarations(source, QStringLiteral("T"), diagnostics);
    QCOMPARE(diagnosticsText(diagnostics), QString());
    QStringList parts;
    for (const auto &s : sections)
        parts << ast::dump(s);
    QCOMPARE(parts.join(QLatin1Char('|')), tree);
}

void TestParser::types()
{
    const QString source = QStringLiteral(
        "TYPE\n"
        "  Color : (Red, Green := 5, Blue);\n"
        "  Pt : STRUCT x : INT; y : INT := 7; END_STRUCT;\n"
        "  Row : ARRAY[1..3] OF REAL;\n"
        "  Pct : INT (0..100) := 50;\n"
        "  Name : STRING[16];\n"
        "  Alias : DINT;\n"
        "  Light : Color := Green;\n"
        "END_TYPE\n");
    Diagnostics diagnostics;
    const auto unit = parseUnit(source, diagnostics);
    QCOMPARE(diagnosticsText(diagnostics), QString());
    QStringList parts;
    for (const auto &t : unit.types)
        parts << t.name + QLatin1Char('=') + ast::dump(t.type)
                + (t.init.kind != ast::Initializer::Kind::None ? QStringLiteral(":=") + ast::dump(t.init) : QString());
    QCOMPARE(parts.join(QStringLiteral(" | ")),
             QStringLiteral("Color=(Red,Green:=5,Blue) | Pt=STRUCT(x:INT; y:INT:=7) | Row=ARRAY[1..3] OF REAL | "
                            "Pct=INT(0..100):=50 | Name=STRING[16] | Alias=DINT | Light=Color:=Green"));
}

void TestParser::instructionList_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("listing");
    auto row = [](const char *name, const char *source, const char *listing) {
        QTest::newRow(name) << QString::fromUtf8(source) << QString::fromUtf8(listing);
    };
    row("deferred", "LD 5\nMUL (6\nADD 7\n)\nST ERG", "LD 5; MUL( 6; ADD 7; ); ST ERG");
    row("labels and jumps", "Loop:\n LD Counter\n NE 0\n JMPC Body (* cond *)\n JMP End_Loop\nBody: LD 1\nEnd_Loop:",
        "Loop:; LD Counter; NE 0; JMPC Body; JMP End_Loop; Body: LD 1; End_Loop:");
    row("modifiers", "LDN a\nANDN b\nORN c\nXORN d\nSTN e\nS f\nR g",
        "LDN a; ANDN b; ORN c; XORN d; STN e; S f; R g");
    row("cal with args", "CAL T1(PT := T#1S)\nLD T1.Q\nST M", "CAL T1 [PT := T#1S]; LD T1.Q; ST M");
    row("calc", "CALC T2(IN := TRUE)\nCALCN T3", "CALC T2 [IN := TRUE]; CALCN T3");
    row("returns", "RET\nRETC\nRETCN", "RET; RETC; RETCN");
    row("open paren without operand", "LD a\nAND(\nLD b\nOR c\n)\nST d", "LD a; AND(; LD b; OR c; ); ST d");
    row("function with operands", "LD g\nSEL 1, 2\nST x", "LD g; SEL 1 [2]; ST x");
    row("negative operand", "LD -5\nADD -2.5", "LD -5; ADD -2.5");
    row("address operands", "LD %IX0.0\nST %QX0.0", "LD %IX0.0; ST %QX0.0");
    row("fb input operator", "LD TRUE\nS1 FF28\nLD C\nLT D", "LD TRUE; S1 FF28; LD C; LT D");
}

void TestParser::instructionList()
{
    QFETCH(QString, source);
    QFETCH(QString, listing);
    Diagnostics diagnostics;
    const auto list = parseIlBody(source, QStringLiteral("T"), diagnostics);
    QCOMPARE(diagnosticsText(diagnostics), QString());
    QCOMPARE(ilText(list), listing);
}

void TestParser::sfc_data()
{
    QTest::addColumn<QString>("body");
    QTest::addColumn<QString>("chart");
    auto row = [](const char *name, const char *source, const char *chart) {
        QTest::newRow(name) << QString::fromUtf8(source) << QString::fromUtf8(chart);
    };
    row("seed steps", "INITIAL_STEP S0: END_STEP\nSTEP S8:\n ACTION_1(L,t#10s,DN1) ;\n ACTION_2(P) ;\n ACTION_3(N) ;\nEND_STEP",
        "(initial_step S0) (step S8 ACTION_1(L,t#10s,DN1) ACTION_2(P) ACTION_3(N))");
    row("st transition", "STEP STEP7: END_STEP\nTRANSITION FROM STEP7 TO STEP8\n := %IX2.4 & %IX2.3 ;\nEND_TRANSITION\nSTEP STEP8: END_STEP",
        "(step STEP7) (step STEP8) (transition STEP7 -> STEP8 := (AND %IX2.4 %IX2.3))");
    row("il transition", "TRANSITION FROM STEP7 TO STEP8:\n LD %IX2.4\n AND %IX2.3\nEND_TRANSITION",
        "(transition STEP7 -> STEP8 il{LD %IX2.4; AND %IX2.3})");
    row("named with priority and divergence", "TRANSITION T1 (PRIORITY := 2) FROM (S1, S2) TO (S3, S4) := x; END_TRANSITION",
        "(transition T1 priority 2 S1,S2 -> S3,S4 := x)");
    row("st action", "INITIAL_STEP S8: ACTION_4(N); END_STEP\nACTION ACTION_4:\n %QX17 := %IX1 & %MX3 & S8.X ;\n FF28(S1 := (C<D));\n %MX10 := FF28.Q;\nEND_ACTION",
        "(initial_step S8 ACTION_4(N)) (action ACTION_4 (:= %QX17 (AND (AND %IX1 %MX3) S8.X)) (call FF28(S1 := (< C D))) (:= %MX10 FF28.Q))");
    row("il action", "INITIAL_STEP S8: END_STEP\nACTION ACTION_4:\n LD S8.X\n AND %IX1\n ST %QX17\n LD C\n LT D\n S1 FF28\nEND_ACTION",
        "(initial_step S8) (action ACTION_4 il{LD S8.X; AND %IX1; ST %QX17; LD C; LT D; S1 FF28})");
}

void TestParser::sfc()
{
    QFETCH(QString, body);
    QFETCH(QString, chart);
    Diagnostics diagnostics;
    const QString source = QStringLiteral("PROGRAM P\nVAR x : BOOL; END_VAR\n") + body + QStringLiteral("\nEND_PROGRAM");
    const auto unit = parseUnit(source, diagnostics);
    QCOMPARE(diagnosticsText(diagnostics), QString());
    QCOMPARE(unit.pous.size(), size_t{1});
    QCOMPARE(unit.pous[0].body.language, ast::Language::SFC);
    QCOMPARE(ast::dump(*unit.pous[0].body.sfc), chart);
}

void TestParser::programUnit()
{
    const QString source = QStringLiteral(
        "FUNCTION Twice : INT\nVAR_INPUT x : INT; END_VAR\nTwice := x * 2;\nEND_FUNCTION\n"
        "FUNCTION_BLOCK Counter\nVAR_INPUT up : BOOL; END_VAR\nVAR_OUTPUT n : INT; END_VAR\n"
        "IF up THEN n := n + 1; END_IF\nEND_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR c : Counter; v : INT; END_VAR\nc(up := TRUE);\nv := Twice(c.n);\nEND_PROGRAM\n"
        "PROGRAM IlProg\nVAR a : INT; END_VAR\nLD 5\nST a\nEND_PROGRAM\n");
    Diagnostics diagnostics;
    const auto unit = parseUnit(source, diagnostics);
    QCOMPARE(diagnosticsText(diagnostics), QString());
    QCOMPARE(unit.pous.size(), size_t{4});
    QCOMPARE(unit.pous[0].kind, ast::PouKind::Function);
    QCOMPARE(ast::dump(*unit.pous[0].returnType), QStringLiteral("INT"));
    QCOMPARE(unit.pous[1].kind, ast::PouKind::FunctionBlock);
    QCOMPARE(ast::dump(unit.pous[1].body.statements), QStringLiteral("(if up {(:= n (+ n 1))})"));
    QCOMPARE(unit.pous[2].name, QStringLiteral("Main"));
    QCOMPARE(ast::dump(unit.pous[2].body.statements), QStringLiteral("(call c(up := TRUE)) (:= v Twice(c.n))"));
    QCOMPARE(unit.pous[2].body.statements[1].location.line, 13);
    QCOMPARE(unit.pous[2].body.statements[1].location.column, 1);
    QCOMPARE(unit.pous[3].body.language, ast::Language::IL);
    QCOMPARE(ilText(unit.pous[3].body.il), QStringLiteral("LD 5; ST a"));
}

void TestParser::configuration()
{
    const QString source = QStringLiteral(
        "CONFIGURATION Plant\n"
        " VAR_GLOBAL g : INT; END_VAR\n"
        " RESOURCE Cpu ON PLC\n"
        "  TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);\n"
        "  TASK Trig(SINGLE := start, PRIORITY := 2);\n"
        "  PROGRAM Main1 WITH Fast : Main;\n"
        "  PROGRAM RETAIN Aux WITH Trig : Helper(x := 1, y => g);\n"
        " END_RESOURCE\n"
        "END_CONFIGURATION\n");
    Diagnostics diagnostics;
    const auto unit = parseUnit(source, diagnostics);
    QCOMPARE(diagnosticsText(diagnostics), QString());
    QCOMPARE(unit.configurations.size(), size_t{1});
    const auto &config = unit.configurations[0];
    QCOMPARE(config.globals.size(), size_t{1});
    QCOMPARE(config.resources.size(), size_t{1});
    const auto &res = config.resources[0];
    QCOMPARE(res.on, QStringLiteral("PLC"));
    QCOMPARE(res.tasks.size(), size_t{2});
    QCOMPARE(ast::dump(*res.tasks[0].interval), QStringLiteral("T#10ms"));
    QCOMPARE(ast::dump(*res.tasks[1].single), QStringLiteral("start"));
    QCOMPARE(res.programs.size(), size_t{2});
    QCOMPARE(res.programs[1].task, QStringLiteral("Trig"));
    QCOMPARE(res.programs[1].type, QStringLiteral("Helper"));
    QVERIFY(res.programs[1].retain);
    QCOMPARE(res.programs[1].args.size(), size_t{2});
}

void TestParser::diagnostics_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("messages");
    auto row = [](const char *name, const char *source, const char *messages) {
        QTest::newRow(name) << QString::fromUtf8(source) << QString::fromUtf8(messages);
    };
    row("equals instead of assign", "PROGRAM P\nVAR a : INT; END_VAR\na = 5;\nb := 1;\nEND_PROGRAM",
        "P:3:1: error: '=' compares two values; to assign a value write ':='. (hint: write a := ...;)");
    row("missing end_if at its if",
        "PROGRAM P\nVAR a : INT; END_VAR\nIF a > 1 THEN\n  a := 1;\nWHILE a < 3 DO a := a + 1; END_WHILE\nEND_PROGRAM",
        "P:3:1: error: This IF has no matching END_IF. (hint: add END_IF; after the last statement that belongs to it)");
    row("missing semicolon", "PROGRAM P\nVAR a : INT; END_VAR\na := 1\na := 2;\nEND_PROGRAM",
        "P:3:7: error: Missing ';' at the end of the statement. (hint: every ST statement ends with ';')");
    row("one typo one message", "PROGRAM P\nVAR a : INT; END_VAR\na := 1 + * 2;\na := 3;\nEND_PROGRAM",
        "P:3:10: error: Expected a value, a variable or a function call but found '*'.");
    row("then missing", "PROGRAM P\nVAR a : INT; END_VAR\nIF a > 1\n a := 2;\nEND_IF;\nEND_PROGRAM",
        "P:4:2: error: Expected THEN but found 'a'.");
    row("bad literal", "PROGRAM P\nVAR a : TIME; END_VAR\na := T#5x;\nEND_PROGRAM",
        "P:3:6: error: 'T#5x' is not valid IEC 61131-3 text. (hint: check the digits and units of the literal, e.g. 16#FF or T#1s500ms)");
    row("initial value with equals", "PROGRAM P\nVAR a : INT = 5; END_VAR\nEND_PROGRAM",
        "P:2:13: error: An initial value is given with ':=', not '='. (hint: write a : ... := value;)");
    row("missing end_var", "PROGRAM P\nVAR a : INT;\na := 1;\nEND_PROGRAM",
        "P:2:1: error: This variable section has no END_VAR. (hint: add END_VAR after its last declaration)");
    row("two independent errors", "PROGRAM P\nVAR a : INT; END_VAR\na = 1;\na := ;\nEND_PROGRAM",
        "P:3:1: error: '=' compares two values; to assign a value write ':='. (hint: write a := ...;)\n"
        "P:4:6: error: Expected a value, a variable or a function call but found ';'.");
    row("missing end_program", "PROGRAM P\nVAR a : INT; END_VAR\na := 1;\n",
        "P:1:1: error: P has no END_PROGRAM. (hint: add END_PROGRAM after its last statement)");
    row("function without type", "FUNCTION F\nVAR_INPUT a : INT; END_VAR\nF := a;\nEND_FUNCTION",
        "F:2:1: error: A FUNCTION needs a result type after its name. (hint: write e.g. FUNCTION F : INT)");
}

void TestParser::diagnostics()
{
    QFETCH(QString, source);
    QFETCH(QString, messages);
    Diagnostics diagnostics;
    parseUnit(source, diagnostics);
    QCOMPARE(diagnosticsText(diagnostics), messages);
}

QTEST_GUILESS_MAIN(TestParser)
#include "tst_parser.moc"
