// Find in Project and the cross-reference list as tables over one project (text bodies,
// declarations, graphical elements, actions, transitions, global lists), the results pane opening
// the place of a hit, and the Edit menu routing Cut/Copy/Paste/Delete/Select All/Find to the part
// with the focus: a text editor directly, any other document through its named actions.
#include "app/documentarea.h"
#include "app/editactions.h"
#include "app/mainwindow.h"
#include "app/projectsearch.h"
#include "app/searchactions.h"
#include "app/searchresultspane.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/globals/globallisteditor.h"
#include "editors/text/codeeditor.h"
#include "editors/text/findreplacebar.h"
#include "editors/text/texteditorwidget.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"
#include "testsettings.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTreeWidget>

using namespace iec;
using namespace iec::app;
using Access = SearchHit::Access;

Q_DECLARE_METATYPE(iec::app::SearchQuery)

namespace {

const char *const kSource = R"(PROGRAM Main
VAR
  Count : INT; (* pieces counted *)
  Limit : INT := 10;
  Timer : TON;
END_VAR
Count := Count + 1;
Timer(IN := Count > Limit, PT := T#1s);
IF Timer.Q THEN
  count := 0;
END_IF;
IO.Lamp := Count > 5;
END_PROGRAM
FUNCTION_BLOCK Pump
VAR_INPUT
  Count : INT;
END_VAR
VAR
  Lamp : BOOL;
END_VAR
Lamp := Count > 0;
END_FUNCTION_BLOCK
PROGRAM Listing
VAR
  Total : INT;
END_VAR
LD Total
ADD 1
ST Total
ST Lamp
END_PROGRAM
CONFIGURATION Config
  RESOURCE Resource ON PLC
    VAR_GLOBAL
      Lamp : BOOL;
    END_VAR
    TASK MainTask(INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM Main WITH MainTask : Main;
  END_RESOURCE
END_CONFIGURATION
)";

model::Project sampleProject()
{
    model::Project project = interp::frontend::readIecText(QString::fromUtf8(kSource), QStringLiteral("Test")).project;
    project.instances.configurations[0].resources[0].globalVars[0].name = QStringLiteral("IO");
    // A ladder action of Main: a contact reads Count, a coil writes Lamp.
    model::PouPart ladder;
    ladder.name = QStringLiteral("Show");
    ladder.body = model::Body::withLanguage(model::BodyLanguage::LD);
    model::Contact contact;
    contact.localId = 7;
    contact.variable = QStringLiteral("Count");
    model::Coil coil;
    coil.localId = 8;
    coil.variable = QStringLiteral("Lamp");
    *ladder.body.elements() = {contact, coil};
    for (model::Pou &pou : project.types.pous) {
        if (pou.name != QLatin1String("Main"))
            continue;
        pou.actions.push_back(ladder);
        pou.pouInterface->varLists.front().variables.front().documentation = model::FormattedText {QStringLiteral("pieces counted"), {}};
    }
    return project;
}

// A hit as one line: place, where, use and text.
QString describe(const SearchHit &hit)
{
    QString where = hit.isDeclaration() ? QStringLiteral("decl") : hit.localId ? QStringLiteral("#%1").arg(*hit.localId)
                                                                               : QStringLiteral("%1:%2").arg(hit.line).arg(hit.column);
    QString line = hit.place + QLatin1Char(' ') + where;
    if (hit.access != Access::None)
        line += QLatin1Char(' ') + ProjectSearch::accessText(hit.access);
    return line;
}

QStringList describeAll(const std::vector<SearchHit> &hits)
{
    QStringList lines;
    for (const SearchHit &hit : hits)
        lines << describe(hit);
    return lines;
}

model::PouId idOf(const model::Project &project, const char *name)
{
    return project.findPou(QString::fromLatin1(name))->id;
}

} // namespace

class TestSearch : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void find_data();
    void find();
    void invalidRegularExpressionIsSaid();
    void crossReferences_data();
    void crossReferences();
    void hitsOpenTheirPlace();
    void crossReferencesOfTheWordUnderTheCursor();
    void goToDefinitionOfAGlobalOpensItsList();
    void editCommandsReachTheFocusedText();
    void editCommandsReachADocumentsNamedActions();
    void findOpensTheEditorsBar();

private:
    QTemporaryDir m_configHome;
};

void TestSearch::initTestCase()
{
    useTestSettings(m_configHome);
}

void TestSearch::find_data()
{
    QTest::addColumn<SearchQuery>("query");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("any case, in text, elements and declarations")
        << SearchQuery {QStringLiteral("count")}
        << QStringList {QStringLiteral("Main 1:1"), QStringLiteral("Main 1:10"), QStringLiteral("Main 2:13"),
               QStringLiteral("Main 4:3"), QStringLiteral("Main 6:12"), QStringLiteral("Main.Show #7"),
               QStringLiteral("Pump 1:9"), QStringLiteral("Main decl"), QStringLiteral("Pump decl")};
    QTest::newRow("match case") << SearchQuery {QStringLiteral("count"), true}
                                << QStringList {QStringLiteral("Main 4:3"), QStringLiteral("Main decl")}; // "counted"
    QTest::newRow("whole word") << SearchQuery {QStringLiteral("Tot"), false, true} << QStringList {};
    QTest::newRow("part of a word") << SearchQuery {QStringLiteral("Tot")}
                                    << QStringList {QStringLiteral("Listing 1:4"), QStringLiteral("Listing 3:4"),
                                           QStringLiteral("Listing decl")};
    QTest::newRow("regular expression")
        << SearchQuery {QStringLiteral("^ST\\s+\\w+"), true, false, true}
        << QStringList {QStringLiteral("Listing 3:1"), QStringLiteral("Listing 4:1")};
    QTest::newRow("global list declaration")
        << SearchQuery {QStringLiteral("lamp : bool")} << QStringList {QStringLiteral("Pump decl"), QStringLiteral("IO decl")};
}

void TestSearch::find()
{
    QFETCH(SearchQuery, query);
    QFETCH(QStringList, expected);
    const SearchResult result = ProjectSearch::find(sampleProject(), query);
    QCOMPARE(result.error, QString());
    QCOMPARE(describeAll(result.hits), expected);
}

void TestSearch::invalidRegularExpressionIsSaid()
{
    const SearchResult result = ProjectSearch::find(sampleProject(), {QStringLiteral("(open"), false, false, true});
    QVERIFY(result.hits.empty());
    QVERIFY2(result.error.startsWith(QStringLiteral("The regular expression is not valid:")), qPrintable(result.error));
}

void TestSearch::crossReferences_data()
{
    QTest::addColumn<QString>("from");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("a program's variable")
        << QStringLiteral("Main") << QStringLiteral("Count")
        << QStringList {QStringLiteral("Main decl declared"), QStringLiteral("Main 1:1 written"),
               QStringLiteral("Main 1:10 read"), QStringLiteral("Main 2:13 read"), QStringLiteral("Main 4:3 written"),
               QStringLiteral("Main 6:12 read"), QStringLiteral("Main.Show #7 read")};
    QTest::newRow("a global, qualified, in IL, LD, and hidden by a local")
        << QStringLiteral("Main") << QStringLiteral("Lamp")
        << QStringList {QStringLiteral("IO decl declared"), QStringLiteral("Main 6:4 written"),
               QStringLiteral("Main.Show #8 written"), QStringLiteral("Listing 4:4 written")};
    QTest::newRow("an FB instance") << QStringLiteral("Main") << QStringLiteral("Timer")
                                    << QStringList {QStringLiteral("Main decl declared"), QStringLiteral("Main 2:1 read"),
                                           QStringLiteral("Main 3:4 read")};
    QTest::newRow("IL load and store") << QStringLiteral("Listing") << QStringLiteral("Total")
                                       << QStringList {QStringLiteral("Listing decl declared"),
                                              QStringLiteral("Listing 1:4 read"), QStringLiteral("Listing 3:4 written")};
}

void TestSearch::crossReferences()
{
    QFETCH(QString, from);
    QFETCH(QString, name);
    QFETCH(QStringList, expected);
    model::ProjectModel model; // gives the POUs their ids
    model.reset(sampleProject());
    const model::Project &project = model.project();
    QCOMPARE(describeAll(ProjectSearch::crossReferences(project, idOf(project, from.toLatin1().constData()), name)), expected);
}

void TestSearch::hitsOpenTheirPlace()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    SearchActions &search = window.searchActions();
    QCOMPARE(search.findInProject({QStringLiteral("Timer.Q")}), 1);
    SearchResultsPane &pane = window.searchResults();
    QCOMPARE(pane.title(), QStringLiteral("1 matches of \"Timer.Q\""));
    QCOMPARE(pane.list()->topLevelItemCount(), 1);
    QCOMPARE(pane.list()->topLevelItem(0)->text(1), QStringLiteral("line 3, column 4"));
    Q_EMIT pane.list()->itemActivated(pane.list()->topLevelItem(0), 0);
    const model::BodyRef main {idOf(window.projectModel().project(), "Main"), model::BodyRef::Part::Pou, {}};
    editors::CodeEditor *editor = window.documents().textEditorFor(main);
    QVERIFY(editor);
    QCOMPARE(editor->textCursor().selectedText(), QStringLiteral("Timer.Q"));
    QCOMPARE(editor->textCursor().blockNumber(), 2);

    // A declaration hit shows the row of the variable.
    QCOMPARE(search.findInProject({QStringLiteral("pieces counted")}), 1);
    Q_EMIT pane.list()->itemActivated(pane.list()->topLevelItem(0), 0);
    editors::DeclarationEditor *declarations = window.documents().declarationEditorFor(main);
    QCOMPARE(declarations->table()->currentIndex().row(), 0);
}

void TestSearch::crossReferencesOfTheWordUnderTheCursor()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    const model::BodyRef main {idOf(window.projectModel().project(), "Main"), model::BodyRef::Part::Pou, {}};
    window.documents().openBody(main);
    editors::CodeEditor *editor = window.documents().textEditorFor(main);
    editor->goToLine(6, 5); // on IO.Lamp
    QVERIFY(window.searchActions().showCrossReferences());
    QCOMPARE(window.searchResults().title(), QStringLiteral("Cross references of Lamp: 4 places"));
}

void TestSearch::goToDefinitionOfAGlobalOpensItsList()
{
    MainWindow window;
    model::Project project = sampleProject();
    std::vector<model::Variable> &globals = project.instances.configurations[0].resources[0].globalVars[0].variables;
    globals.insert(globals.begin(), model::Variable {.name = QStringLiteral("Alarm")});
    window.projectModel().reset(project);
    const model::BodyRef main {idOf(window.projectModel().project(), "Main"), model::BodyRef::Part::Pou, {}};
    DocumentArea &documents = window.documents();
    const editors::GlobalListRef io {QStringLiteral("Config"), QStringLiteral("Resource"), QStringLiteral("IO")};
    // CODESYS's List.Variable, and the global alone: the list's tab with the variable's row current.
    for (const QString &path : {QStringLiteral("IO.Lamp"), QStringLiteral("lamp")}) {
        documents.openBody(main);
        QVERIFY2(documents.goToDefinition(main, path), qPrintable(path));
        editors::GlobalListEditor *list = documents.globalListEditorFor(io);
        QVERIFY(list);
        QCOMPARE(documents.currentWidget(), list);
        QCOMPARE(list->table()->currentIndex().row(), 1);
    }
    // No such variable in the list, no list of that name: nothing to go to.
    QVERIFY(!documents.goToDefinition(main, QStringLiteral("IO.Missing")));
    QVERIFY(!documents.goToDefinition(main, QStringLiteral("HMI.Lamp")));
}

void TestSearch::editCommandsReachTheFocusedText()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.projectModel().reset(sampleProject());
    const model::BodyRef main {idOf(window.projectModel().project(), "Main"), model::BodyRef::Part::Pou, {}};
    window.documents().openBody(main);
    editors::CodeEditor *editor = window.documents().textEditorFor(main);
    editor->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget *>(editor));
    EditActions &edit = window.editActions();
    QVERIFY(edit.run(EditActions::Command::SelectAll));
    QCOMPARE(editor->textCursor().selectedText().size(), editor->toPlainText().size());
    editor->goToLine(1, 1);
    QTextCursor cursor = editor->textCursor();
    cursor.movePosition(QTextCursor::EndOfWord, QTextCursor::KeepAnchor);
    editor->setTextCursor(cursor);
    QVERIFY(edit.run(EditActions::Command::Copy));
    QCOMPARE(QApplication::clipboard()->text(), QStringLiteral("Count"));
    QVERIFY(edit.run(EditActions::Command::Delete));
    QVERIFY(editor->document()->findBlockByNumber(0).text().startsWith(QStringLiteral(" := Count + 1;")));
    QVERIFY(edit.run(EditActions::Command::Paste));
    QVERIFY(editor->document()->findBlockByNumber(0).text().startsWith(QStringLiteral("Count := Count + 1;")));
    QVERIFY(edit.run(EditActions::Command::Cut));
    QCOMPARE(QApplication::clipboard()->text(), QStringLiteral("Count")); // nothing selected: nothing cut
    // The menu shows the keys, which stay with the editors.
    QCOMPARE(edit.action(EditActions::Command::Copy)->shortcut(), QKeySequence(QKeySequence::Copy));
    QCOMPARE(edit.action(EditActions::Command::Copy)->shortcutContext(), Qt::WidgetShortcut);
}

void TestSearch::editCommandsReachADocumentsNamedActions()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    // A document that is no text editor: its actions follow the convention (a diagram editor's).
    auto *diagram = new QWidget;
    QStringList triggered;
    for (const char *name : {"diagramCut", "diagramCopy", "diagramPaste", "diagramDelete", "diagramSelectAll"}) {
        auto *action = new QAction(diagram);
        action->setObjectName(QString::fromLatin1(name));
        connect(action, &QAction::triggered, [&triggered, name] { triggered << QString::fromLatin1(name); });
        diagram->addAction(action);
    }
    window.documents().addTab(diagram, QStringLiteral("Diagram"));
    window.documents().setCurrentWidget(diagram);
    diagram->setFocusPolicy(Qt::StrongFocus);
    diagram->setFocus();
    EditActions &edit = window.editActions();
    for (const auto command : {EditActions::Command::Cut, EditActions::Command::Copy, EditActions::Command::Paste,
             EditActions::Command::Delete, EditActions::Command::SelectAll})
        QVERIFY(edit.run(command));
    QCOMPARE(triggered, (QStringList {QStringLiteral("diagramCut"), QStringLiteral("diagramCopy"),
                            QStringLiteral("diagramPaste"), QStringLiteral("diagramDelete"), QStringLiteral("diagramSelectAll")}));
    // A standard shortcut is as good as a name.
    auto *byKey = new QAction(diagram);
    byKey->setShortcut(QKeySequence::Find);
    bool found = false;
    connect(byKey, &QAction::triggered, [&found] { found = true; });
    diagram->addAction(byKey);
    QVERIFY(edit.run(EditActions::Command::Find));
    QVERIFY(found);
    QVERIFY(!edit.run(EditActions::Command::Replace)); // nothing takes it
}

void TestSearch::findOpensTheEditorsBar()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.projectModel().reset(sampleProject());
    const model::BodyRef main {idOf(window.projectModel().project(), "Main"), model::BodyRef::Part::Pou, {}};
    auto *text = window.documents().openBody(main)->findChild<editors::TextEditorWidget *>();
    text->editor()->setFocus();
    QVERIFY(window.editActions().run(EditActions::Command::Replace));
    QVERIFY(text->findBar()->isVisible());
    QVERIFY(text->findBar()->isReplaceShown());
}

QTEST_MAIN(TestSearch)
#include "tst_search.moc"
