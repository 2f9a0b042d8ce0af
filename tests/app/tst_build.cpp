#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/projecttemplates.h"
#include "editors/text/codeeditor.h"
#include "model/projectmodel.h"

#include <QTemporaryDir>
#include <QTest>

using namespace iec::app;
using namespace iec::model;

class TestBuild : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void compilerDiagnosticsBecomeLocatedMessages_data();
    void compilerDiagnosticsBecomeLocatedMessages();
    void buildListsUnderlinesAndOpensTheLine();
    void anotherProjectStartsWithoutTheOldMessages();

private:
    QTemporaryDir m_configHome;
};

namespace {

Project programWithBody(const QString &text)
{
    Project project;
    Pou pou;
    pou.name = QStringLiteral("Main");
    Interface declarations;
    VarList locals;
    Variable counter;
    counter.name = QStringLiteral("Counter");
    counter.type.kind = ElementaryType{QStringLiteral("INT")};
    locals.variables.push_back(counter);
    declarations.varLists.push_back(locals);
    pou.pouInterface = declarations;
    Body body = Body::withLanguage(BodyLanguage::ST);
    body.setText(text);
    pou.bodies.push_back(body);
    project.types.pous.push_back(pou);
    return project;
}

} // namespace

void TestBuild::initTestCase()
{
    qputenv("XDG_CONFIG_HOME", m_configHome.path().toLocal8Bit());
    QCoreApplication::setOrganizationName(QStringLiteral("IEC Studio Tests"));
}

void TestBuild::compilerDiagnosticsBecomeLocatedMessages_data()
{
    QTest::addColumn<QString>("body");
    QTest::addColumn<int>("errors");
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("column");
    QTest::newRow("clean") << QStringLiteral("Counter := Counter + 1;") << 0 << 0 << 0;
    QTest::newRow("unknown variable") << QStringLiteral("Counter := Counter + 1;\nCountr := 0;") << 1 << 2 << 1;
    QTest::newRow("missing END_IF") << QStringLiteral("IF Counter > 3 THEN\n  Counter := 0;\n") << 1 << 1 << 1;
}

void TestBuild::compilerDiagnosticsBecomeLocatedMessages()
{
    QFETCH(QString, body);
    QFETCH(int, errors);
    QFETCH(int, line);
    QFETCH(int, column);
    const QList<Message> messages = compileMessages(programWithBody(body));

    QCOMPARE(int(messages.size()), errors);
    if (errors == 0)
        return;
    const Message &first = messages.front();
    QCOMPARE(first.severity, Message::Severity::Error);
    QCOMPARE(first.pouName, QStringLiteral("Main"));
    QCOMPARE(first.line, line);
    QCOMPARE(first.column, column);
    QVERIFY(!first.text.isEmpty());
}

void TestBuild::buildListsUnderlinesAndOpensTheLine()
{
    MainWindow window;
    window.projectModel().reset(programWithBody(QStringLiteral("Counter := Counter + 1;\nCountr := 0;")));
    const BodyRef main{window.projectModel().project().types.pous.front().id, BodyRef::Part::Pou, {}};
    window.documents().openBody(main);
    iec::editors::CodeEditor *editor = window.documents().textEditorFor(main);
    QVERIFY(editor);

    QVERIFY(!window.buildController().build());
    QCOMPARE(window.messagesPane().model().count(Message::Severity::Error), 1);
    QCOMPARE(editor->diagnostics().size(), 1);
    QCOMPARE(editor->diagnostics().front().line, 2);
    QCOMPARE(editor->diagnostics().front().length, 6); // the whole of "Countr"

    // Double-clicking the message puts the cursor on the line it names.
    editor->moveCursor(QTextCursor::Start);
    window.buildController().openLocation(window.messagesPane().model().message(0));
    QCOMPARE(editor->textCursor().blockNumber(), 1);

    // Fixing the typo and building again clears the message and the underline.
    editor->setPlainText(QStringLiteral("Counter := Counter + 1;\nCounter := 0;"));
    QVERIFY(window.buildController().build());
    QCOMPARE(window.messagesPane().model().rowCount(), 0);
    QVERIFY(editor->diagnostics().isEmpty());
}

void TestBuild::anotherProjectStartsWithoutTheOldMessages()
{
    MainWindow window;
    const auto buildWithAnError = [&window] {
        window.projectModel().reset(programWithBody(QStringLiteral("Countr := 0;")));
        QVERIFY(!window.buildController().build());
        QCOMPARE(window.messagesPane().model().rowCount(), 1);
    };
    buildWithAnError();
    QString error;
    QVERIFY2(window.openExample(QStringLiteral(":/examples/mixing_tank.xml"), &error), qPrintable(error));
    QCOMPARE(window.messagesPane().model().rowCount(), 0);
    buildWithAnError();
    window.newProjectFromTemplate(ProjectTemplate::ST);
    QCOMPARE(window.messagesPane().model().rowCount(), 0);
}

QTEST_MAIN(TestBuild)
#include "tst_build.moc"
