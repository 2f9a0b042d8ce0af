// Deep programs (20,000 parentheses, 50,000 NOTs, 10,000 nested IFs ...) give one located message
// at the nesting limit (limits.h); long ones (a sum of 100,000 terms, 100,000 statements) compile
// and run, through the text and through the model. Chains the parser cannot limit (constants
// defined by constants, types by types) never overflow the stack.
#include "deepinputs.h"
#include "tracerunner.h"

#include "interpreter/compiler/astdump.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/compiler/limits.h"
#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include <QTest>
#include <QThread>

using namespace iec::interp;

class TestDeepInputs : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void testLimitsMatchTheCompiler();
    void deepProgramsGiveOneMessage_data();
    void deepProgramsGiveOneMessage();
    void deepProgramsThroughTheModelGiveOneMessage_data();
    void deepProgramsThroughTheModelGiveOneMessage();
    void nestingUpToTheLimitCompiles_data();
    void nestingUpToTheLimitCompiles();
    void longProgramsCompileAndRun_data();
    void longProgramsCompileAndRun();
    void longSumThroughTheModel();
    void longInitialValueSurvivesTheModel();
    void deepExpressionsCopyAndPrint();
    void nestingAtTheLimitOnASmallStack();
    void deepIlConditionGivesOneMessage();
    void constantDefinedByItselfIsReported();
    void chainsOfConstantsAndTypesNeverCrash_data();
    void chainsOfConstantsAndTypesNeverCrash();
};

void TestDeepInputs::testLimitsMatchTheCompiler()
{
    QCOMPARE(deepinputs::kMaxNesting, limits::kMaxNesting);
    QCOMPARE(deepinputs::kMaxTypeNesting, limits::kMaxTypeNesting);
}

void TestDeepInputs::deepProgramsGiveOneMessage_data()
{
    QTest::addColumn<QString>("variables");
    QTest::addColumn<QString>("body");
    QTest::addColumn<QString>("expected");
    for (const deepinputs::Deep &deep : deepinputs::deepPrograms())
        QTest::newRow(deep.name) << deep.variables << deep.body
                                 << QStringLiteral("%1:%2: error: %3").arg(deep.line).arg(deep.column).arg(deep.message);
}

// One message at the place where the limit is passed, and nothing else: no crash, no cascade.
void TestDeepInputs::deepProgramsGiveOneMessage()
{
    QFETCH(QString, variables);
    QFETCH(QString, body);
    QFETCH(QString, expected);
    Diagnostics diagnostics;
    QVERIFY(!compileText(deepinputs::program(variables, body), diagnostics));
    QStringList found; // without the hints
    for (const Diagnostic &d : diagnostics.all())
        found << d.toString().section(QStringLiteral(" (hint: "), 0, 0);
    QCOMPARE(found.join(QStringLiteral(" | ")), QStringLiteral("Main:") + expected);
}

void TestDeepInputs::deepProgramsThroughTheModelGiveOneMessage_data()
{
    deepProgramsGiveOneMessage_data();
}

// The IDE's path: the declarations are model values, the body is text in the model, parsed when
// the project compiles.
void TestDeepInputs::deepProgramsThroughTheModelGiveOneMessage()
{
    QFETCH(QString, variables);
    QFETCH(QString, body);
    QFETCH(QString, expected);
    const QString message = expected.section(QStringLiteral("error: "), 1);
    frontend::TextReadResult read = frontend::readIecText(deepinputs::program(variables, QString()), QStringLiteral("p"));
    if (read.diagnostics.hasErrors()) { // a declaration: refused while reading
        QCOMPARE(read.diagnostics.all().size(), size_t(1));
        QCOMPARE(read.diagnostics.all().front().message, message);
        return;
    }
    read.project.types.pous.front().bodies.front().setText(body);
    Diagnostics diagnostics;
    QVERIFY(!frontend::compileProject(read.project, diagnostics));
    QCOMPARE(diagnostics.all().size(), size_t(1));
    QCOMPARE(diagnostics.all().front().message, message);
    QCOMPARE(diagnostics.all().front().pou, QStringLiteral("Main"));
}

void TestDeepInputs::nestingUpToTheLimitCompiles_data()
{
    using deepinputs::program;
    using deepinputs::repeated;
    const int n = limits::kMaxNesting;
    const QString x = QStringLiteral("x : DINT; b : BOOL;");
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("variable");
    QTest::addColumn<QString>("value");
    QTest::newRow("1000 parentheses") << program(x, QStringLiteral("x := ") + repeated(QStringLiteral("("), n) + QStringLiteral("7")
                                                        + repeated(QStringLiteral(")"), n) + QStringLiteral(";"))
                                      << "x" << "7";
    QTest::newRow("1000 NOTs") << program(x, QStringLiteral("b := ") + repeated(QStringLiteral("NOT "), n) + QStringLiteral("b;"))
                               << "b" << "FALSE";
    QTest::newRow("999 NOTs") << program(x, QStringLiteral("b := ") + repeated(QStringLiteral("NOT "), n - 1) + QStringLiteral("b;"))
                              << "b" << "TRUE";
    QTest::newRow("1000 nested IFs") << program(x, repeated(QStringLiteral("IF NOT b THEN\n"), n) + QStringLiteral("x := 5;\n")
                                                       + repeated(QStringLiteral("END_IF;\n"), n))
                                     << "x" << "5";
    QTest::newRow("40 nested ARRAY OF")
        << program(QStringLiteral("x : DINT; m : ") + repeated(QStringLiteral("ARRAY[1..1] OF "), limits::kMaxTypeNesting) + QStringLiteral("DINT;"),
               QStringLiteral("m") + repeated(QStringLiteral("[1]"), limits::kMaxTypeNesting) + QStringLiteral(" := 6;\nx := m")
                   + repeated(QStringLiteral("[1]"), limits::kMaxTypeNesting) + QStringLiteral(";"))
        << "x" << "6";
}

void TestDeepInputs::nestingUpToTheLimitCompiles()
{
    QFETCH(QString, source);
    QFETCH(QString, variable);
    QFETCH(QString, value);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QVERIFY2(module, qPrintable(testing::errorsOf(diagnostics)));
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(1));
    QCOMPARE(runtime.read(QStringLiteral("Main.") + variable).value_or(QString()), value);
}

void TestDeepInputs::longProgramsCompileAndRun_data()
{
    using deepinputs::program;
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("variable");
    QTest::addColumn<QString>("value");
    QTest::newRow("sum of 100000 terms") << deepinputs::sumOfOnes(100'000) << "x" << "100000";
    QString statements;
    for (int i = 0; i < 100'000; ++i)
        statements += QStringLiteral("x := x + 1;\n");
    QTest::newRow("100000 statements") << program(QStringLiteral("x : DINT;"), statements) << "x" << "100000";
    QString elsifs = QStringLiteral("IF x = 0 THEN x := 1;\n");
    for (int i = 1; i < 10'000; ++i)
        elsifs += QStringLiteral("ELSIF x = %1 THEN x := %2;\n").arg(i).arg(i + 1);
    elsifs += QStringLiteral("END_IF;");
    QTest::newRow("ELSIF chain of 10000") << program(QStringLiteral("x : DINT;"), elsifs) << "x" << "1";
    QString conjunction = QStringLiteral("b := a");
    for (int i = 1; i < 100'000; ++i)
        conjunction += QStringLiteral(" AND a");
    QTest::newRow("AND of 100000 variables") << program(QStringLiteral("a : BOOL := TRUE; b : BOOL;"), conjunction + QStringLiteral(";"))
                                             << "b" << "TRUE";
    QString mixed = QStringLiteral("x := 2");
    for (int i = 1; i < 30'000; ++i)
        mixed += QStringLiteral(" * 1 + 1 - 1");
    QTest::newRow("30000 mixed operators") << program(QStringLiteral("x : DINT;"), mixed + QStringLiteral(";")) << "x" << "2";
}

void TestDeepInputs::longProgramsCompileAndRun()
{
    QFETCH(QString, source);
    QFETCH(QString, variable);
    QFETCH(QString, value);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    QVERIFY2(module, qPrintable(testing::errorsOf(diagnostics).left(2000)));
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(1));
    QCOMPARE(runtime.read(QStringLiteral("Main.") + variable).value_or(QString()), value);
}

// The body keeps its text in the model and compiles from there.
void TestDeepInputs::longSumThroughTheModel()
{
    const frontend::TextReadResult read = frontend::readIecText(deepinputs::sumOfOnes(100'000), QStringLiteral("p"));
    QVERIFY(!read.diagnostics.hasErrors());
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(read.project, diagnostics);
    QVERIFY2(module, qPrintable(testing::errorsOf(diagnostics).left(2000)));
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(1));
    QCOMPARE(runtime.read(QStringLiteral("Main.x")).value_or(QString()), QStringLiteral("100000"));
}

// An initial value is stored in the model as the text of its expression: printed without the
// parentheses a left-leaning chain does not need, it reads back as it was, however long.
void TestDeepInputs::longInitialValueSurvivesTheModel()
{
    QString sum = QStringLiteral("1");
    for (int i = 1; i < 50'000; ++i)
        sum += QStringLiteral(" + 1");
    const QString source = deepinputs::program(QStringLiteral("x : DINT := ") + sum + QStringLiteral(";"), QString());
    const frontend::TextReadResult read = frontend::readIecText(source, QStringLiteral("p"));
    QVERIFY(!read.diagnostics.hasErrors());
    const QString printed = frontend::printProject(read.project);
    QVERIFY2(printed.contains(QStringLiteral("x : DINT := ") + sum + QLatin1Char(';')), qPrintable(printed.left(200)));
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(read.project, diagnostics);
    QVERIFY2(module, qPrintable(testing::errorsOf(diagnostics).left(2000)));
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(1));
    QCOMPARE(runtime.read(QStringLiteral("Main.x")).value_or(QString()), QStringLiteral("50000"));
}

// A left-leaning tree of 100,000 levels is copied, destroyed, dumped and printed without
// recursion; the printed text parses to the same tree.
void TestDeepInputs::deepExpressionsCopyAndPrint()
{
    QString sum = QStringLiteral("a");
    for (int i = 1; i < 100'000; ++i)
        sum += i % 2 ? QStringLiteral(" - b") : QStringLiteral(" + f(c, d := e)");
    Diagnostics diagnostics;
    const QString statement = QStringLiteral("x := ") + sum + QLatin1Char(';');
    const std::vector<ast::Stmt> parsed = parseStBody(statement, QStringLiteral("Main"), diagnostics);
    QVERIFY(!diagnostics.hasErrors());
    QCOMPARE(parsed.size(), size_t(1));
    const ast::Expr &tree = parsed.front().value;
    ast::Expr copy = tree;
    const QString dumped = ast::dump(tree);
    QCOMPARE(ast::dump(copy), dumped);
    QVERIFY(dumped.startsWith(QStringLiteral("(- (+ (- (+ ")));
    QCOMPARE(ast::sourceText(copy), sum);
    ast::Expr assigned;
    assigned = copy;
    copy = ast::Expr();
    QCOMPARE(ast::dump(assigned), dumped);
    // Precedence decides the parentheses, never the depth.
    const std::vector<ast::Stmt> mixed = parseStBody(QStringLiteral("x := (a - (b - c)) * (d + e) - -(-5) AND NOT (f OR g);"), QStringLiteral("Main"), diagnostics);
    QCOMPARE(ast::sourceText(mixed.front().value), QStringLiteral("(a - (b - c)) * (d + e) - -(-5) AND NOT (f OR g)"));
}

// The parser's entry points and the compile move to the compiler's own stack: a thread with a
// small stack (an editor checking what is typed, a GUI thread on Windows with 1 MB) parses and
// compiles nesting at the limit, which needs several MB under AddressSanitizer.
void TestDeepInputs::nestingAtTheLimitOnASmallStack()
{
    const int n = limits::kMaxNesting;
    const QString expression = deepinputs::repeated(QStringLiteral("("), n) + QStringLiteral("7") + deepinputs::repeated(QStringLiteral(")"), n);
    const QString source = deepinputs::program(QStringLiteral("x : DINT;"), QStringLiteral("x := ") + expression + QLatin1Char(';'));
    QString parsed, compiled, read;
    const std::unique_ptr<QThread> thread(QThread::create([&] {
        Diagnostics diagnostics;
        const QString statement = QStringLiteral("x := ") + expression + QLatin1Char(';');
        const std::vector<ast::Stmt> body = parseStBody(statement, QStringLiteral("Main"), diagnostics);
        parsed = body.size() == 1 && !diagnostics.hasErrors() ? ast::sourceText(body.front().value) : testing::errorsOf(diagnostics);
        compiled = compileText(source, diagnostics) ? QStringLiteral("compiled") : testing::errorsOf(diagnostics);
        read = frontend::readIecText(source, QStringLiteral("p")).diagnostics.hasErrors() ? QStringLiteral("errors") : QStringLiteral("read");
    }));
    thread->setStackSize(256 * 1024);
    thread->start();
    QVERIFY(thread->wait(QDeadlineTimer(120'000)));
    QCOMPARE(parsed, QStringLiteral("7")); // parentheses that change nothing are not kept
    QCOMPARE(compiled, QStringLiteral("compiled"));
    QCOMPARE(read, QStringLiteral("read"));
}

// A transition condition in IL with more NOTs than an expression may nest: one message.
void TestDeepInputs::deepIlConditionGivesOneMessage()
{
    QString il = QStringLiteral("LD x\n");
    for (int i = 0; i < 5000; ++i)
        il += QStringLiteral("NOT\n");
    const QString source = QStringLiteral("PROGRAM Main\nVAR x : BOOL; END_VAR\n"
                                          "INITIAL_STEP S1: END_STEP\nSTEP S2: END_STEP\n"
                                          "TRANSITION FROM S1 TO S2 := x; END_TRANSITION\n"
                                          "TRANSITION FROM S2 TO S1 : %1END_TRANSITION\nEND_PROGRAM\n").arg(il);
    // Textual SFC is lowered by the front end (compileUnit), as for a .st file.
    Diagnostics diagnostics;
    frontend::ProjectUnit unit;
    unit.unit = parseUnit(source, diagnostics);
    QVERIFY(!diagnostics.hasErrors());
    QVERIFY(!frontend::compileUnit(unit, diagnostics));
    QCOMPARE(diagnostics.all().size(), size_t(1));
    QCOMPARE(diagnostics.all().front().message, QStringLiteral("This IL condition is nested too deeply (more than 1000 levels)."));
}

// Once, at the constant whose value is needed first, instead of an endless recursion.
void TestDeepInputs::constantDefinedByItselfIsReported()
{
    Diagnostics diagnostics;
    QVERIFY(!compileText(QStringLiteral("PROGRAM Main\nVAR CONSTANT\na : INT := b + 1;\nb : INT := a;\nEND_VAR\n"
                                        "VAR x : INT; END_VAR\nx := a;\nEND_PROGRAM\n"),
                         diagnostics));
    QCOMPARE(testing::errorsOf(diagnostics), QStringLiteral("Main:4:12: error: This constant is defined in terms of itself."));
}

void TestDeepInputs::chainsOfConstantsAndTypesNeverCrash_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<int>("links");
    QTest::addColumn<QString>("fault"); // when it runs
    const int n = 20'000;
    QString constants = QStringLiteral("PROGRAM Main\nVAR CONSTANT\n");
    for (int i = 0; i < n; ++i)
        constants += QStringLiteral("c%1 : DINT := c%2 + 1;\n").arg(i).arg(i + 1);
    constants += QStringLiteral("c%1 : DINT := 0;\nEND_VAR\nVAR x : DINT; END_VAR\nx := c0;\nEND_PROGRAM\n").arg(n);
    QTest::newRow("constants defined by constants") << constants << n << QString();
    QString aliases = QStringLiteral("TYPE\n");
    for (int i = 0; i < n; ++i)
        aliases += QStringLiteral("T%1 : T%2;\n").arg(i).arg(i + 1);
    aliases += QStringLiteral("T%1 : DINT;\nEND_TYPE\nPROGRAM Main\nVAR x : T0; END_VAR\nx := %1;\nEND_PROGRAM\n").arg(n);
    QTest::newRow("types defined by types") << aliases << n << QString();
    QString blocks;
    for (int i = 0; i < n; ++i)
        blocks += QStringLiteral("FUNCTION_BLOCK B%1\nVAR inner : B%2; END_VAR\nEND_FUNCTION_BLOCK\n").arg(i).arg(i + 1);
    blocks += QStringLiteral("FUNCTION_BLOCK B%1\nVAR_OUTPUT y : DINT; END_VAR\ny := %1;\nEND_FUNCTION_BLOCK\n"
                             "PROGRAM Main\nVAR b : B0; x : DINT; END_VAR\nx := %1;\nEND_PROGRAM\n").arg(n);
    QTest::newRow("blocks inside blocks") << blocks << n << QString();
    QString calls;
    for (int i = 0; i < n; ++i)
        calls += QStringLiteral("FUNCTION F%1 : DINT\nVAR_INPUT v : DINT; END_VAR\nF%1 := F%2(v) ;\nEND_FUNCTION\n").arg(i).arg(i + 1);
    calls += QStringLiteral("FUNCTION F%1 : DINT\nVAR_INPUT v : DINT; END_VAR\nF%1 := v + %1;\nEND_FUNCTION\n"
                            "PROGRAM Main\nVAR x : DINT; END_VAR\nx := F0(0);\nEND_PROGRAM\n").arg(n);
    // The VM allows 256 nested calls (vm.cpp): running, it stops with a fault.
    QTest::newRow("functions calling functions") << calls << n << QStringLiteral("Calls are nested too deeply.");
}

// Chains the parser cannot limit (each link is flat text): the compiler either follows them to
// the end or stops with one message when its stack budget is spent; it never overflows.
void TestDeepInputs::chainsOfConstantsAndTypesNeverCrash()
{
    QFETCH(QString, source);
    QFETCH(int, links);
    QFETCH(QString, fault);
    Diagnostics diagnostics;
    const auto module = compileText(source, diagnostics);
    if (module) {
        Runtime runtime(module);
        runtime.vm().budgetPerRun = 10'000'000;
        QCOMPARE(runtime.runCycles(1), fault.isEmpty());
        QCOMPARE(runtime.fault() ? runtime.fault()->message : QString(), fault);
        if (fault.isEmpty())
            QCOMPARE(runtime.read(QStringLiteral("Main.x")).value_or(QString()), QString::number(links));
        return;
    }
    QCOMPARE(diagnostics.all().size(), size_t(1));
    QCOMPARE(diagnostics.all().front().message, QStringLiteral("This is nested too deeply to compile."));
}

QTEST_GUILESS_MAIN(TestDeepInputs)
#include "tst_deepinputs.moc"
