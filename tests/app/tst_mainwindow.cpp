#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/importexport.h"
#include "app/importexportactions.h"
#include "app/messagespane.h"
#include "app/projectsymbols.h"
#include "app/examples.h"
#include "app/listmenus.h"
#include "app/mainwindow.h"
#include "app/projectcommands.h"
#include "app/projecttreeactions.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "app/recentfiles.h"
#include "app/recoverymanager.h"
#include "app/settingsdialog.h"
#include "app/undostacks.h"
#include "editors/datatypes/datatypeeditor.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/declarations/declarationtablemodel.h"
#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "model/plcopen/reader.h"
#include "model/projectmodel.h"
#include "model/undo/datatypecommands.h"

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QSplitter>
#include <QTableView>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QUndoGroup>
#include <QUndoStack>

using namespace iec::app;

class TestMainWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void init();
    void opensWithMenusAndDocks();
    void languageSettingRetitlesMenus_data();
    void languageSettingRetitlesMenus();
    void settingsPersistAndClamp();
    void settingsDialogEditsACopy();
    void windowLayoutIsRestored();
    void openEditSaveReopen();
    void openingAMissingFileKeepsTheProject();
    void iecTextOpensAsAnUntitledProject();
    void treeOperationsUndoOnTheProjectStack();
    void activeUndoStackFollowsTheDocuments();
    void undoingTypingBackToTheSavedTextIsClean();
    void treeActionsFollowTheCurrentItem();
    void renamingInPlaceIsUndoable();
    void editUndoWorksOnTypingOrOnTheActiveStack();
    void ctrlYRedoesToo();
    void renameKeepsTypingNotYetPushed();
    void windowMenuListsAndCyclesDocuments();
    void declarationsAreAboveThePouBody();
    void recentFilesKeepOrderAndCap();
    void recentFileThatIsGoneIsRemoved();
    void examplesAreListedAndOpenUntitled();
    void autosaveWritesARecoveryFileThatReadsBack();
    void autosaveIntervalFollowsTheSettings();
    void crashLeavesARecoveryThatIsOfferedAndRestores();
    void recoveryOlderThanItsProjectIsNotOffered();
    void createTypeBuildFixSaveCloseReopen();
    void dataTypeOpensInATabThatFollowsTheType();
    void undoInTheDeclarationTableUndoesTheTableEdit();
    void goToDefinitionShowsDeclarationsAndOpensPous();
    void completionComesFromTheModel();
    void autoDeclareGuessesTheType_data();
    void autoDeclareGuessesTheType();
    void autoDeclareInADiagramTakesTheBoxType();
    void importMergesAndExportWritesTheSelection();

private:
    QTemporaryDir m_configHome;
};

namespace {

QStringList menuTitles(const MainWindow &window)
{
    QStringList titles;
    for (QAction *action : window.menuBar()->actions())
        titles << action->text();
    return titles;
}

void deliverLanguageChange()
{
    // Qt posts LanguageChange to every widget; the event loop would deliver it.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

} // namespace

void TestMainWindow::initTestCase()
{
    // Keep the user's real settings out of the tests.
    QVERIFY(m_configHome.isValid());
    qputenv("XDG_CONFIG_HOME", m_configHome.path().toLocal8Bit());
    QCoreApplication::setOrganizationName(QStringLiteral("IEC Studio Tests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_mainwindow"));
    // Recovery files go to a test location, never into the user's data.
    QStandardPaths::setTestModeEnabled(true);
}

void TestMainWindow::init()
{
    QSettings store;
    store.clear();
    store.setValue(QStringLiteral("ui/language"), QStringLiteral("en"));
    QDir(RecoveryManager::directory()).removeRecursively();
}

void TestMainWindow::opensWithMenusAndDocks()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));

    QCOMPARE(menuTitles(window),
        (QStringList {QStringLiteral("&File"), QStringLiteral("&Edit"), QStringLiteral("&View"),
            QStringLiteral("&Insert"), QStringLiteral("&Project"), QStringLiteral("&Online"), QStringLiteral("&Window"),
            QStringLiteral("&Help")}));
    auto *projectDock = window.findChild<QDockWidget *>(QStringLiteral("projectDock"));
    QVERIFY(projectDock);
    QVERIFY(projectDock->isVisible());
    // An empty project shows the six folders with nothing in them.
    const QAbstractItemModel *tree = window.projectTree().model();
    QCOMPARE(tree->rowCount(), 6);
    for (int row = 0; row < tree->rowCount(); ++row)
        QCOMPARE(tree->rowCount(tree->index(row, 0)), 0);
    QVERIFY(window.findChild<QDockWidget *>(QStringLiteral("messagesDock"))->isVisible());
    QVERIFY(window.close());
}

void TestMainWindow::languageSettingRetitlesMenus_data()
{
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("fileMenu");
    QTest::addColumn<QString>("helpMenu");
    QTest::newRow("de") << QStringLiteral("de") << QStringLiteral("&Datei") << QStringLiteral("&Hilfe");
    QTest::newRow("zh_CN") << QStringLiteral("zh_CN") << QStringLiteral("文件(&F)") << QStringLiteral("帮助(&H)");
    QTest::newRow("en") << QStringLiteral("en") << QStringLiteral("&File") << QStringLiteral("&Help");
}

void TestMainWindow::languageSettingRetitlesMenus()
{
    QFETCH(QString, language);
    QFETCH(QString, fileMenu);
    QFETCH(QString, helpMenu);
    MainWindow window;
    Settings settings = window.settings();
    settings.uiLanguage = language;

    window.applySettings(settings);
    deliverLanguageChange();

    const QStringList titles = menuTitles(window);
    QCOMPARE(titles.first(), fileMenu);
    QCOMPARE(titles.last(), helpMenu);
    // The choice is stored, so the next start uses it.
    QCOMPARE(QSettings().value(QStringLiteral("ui/language")).toString(), language);

    settings.uiLanguage = QStringLiteral("en");
    window.applySettings(settings);
    deliverLanguageChange();
    QCOMPARE(menuTitles(window).first(), QStringLiteral("&File"));
}

void TestMainWindow::settingsPersistAndClamp()
{
    Settings settings;
    settings.uiLanguage = QStringLiteral("de");
    settings.gridSize = 20;
    settings.autosaveMinutes = 0;
    settings.editorFont = QFont(QStringLiteral("DejaVu Sans Mono"), 13);
    {
        QSettings store;
        settings.save(store);
    }
    QCOMPARE(Settings::load(QSettings()), settings);

    QSettings store;
    store.setValue(QStringLiteral("diagram/gridSize"), 100000);
    store.setValue(QStringLiteral("project/autosaveMinutes"), -3);
    const Settings clamped = Settings::load(store);
    QCOMPARE(clamped.gridSize, 100);
    QCOMPARE(clamped.autosaveMinutes, 0);
}

void TestMainWindow::settingsDialogEditsACopy()
{
    Settings original;
    original.gridSize = 10;
    SettingsDialog dialog(original);
    auto *language = dialog.findChild<QComboBox *>(QStringLiteral("language"));
    QCOMPARE(language->count(), 4); // system + three languages
    language->setCurrentIndex(language->findData(QStringLiteral("zh_CN")));
    dialog.findChild<QSpinBox *>(QStringLiteral("gridSize"))->setValue(25);
    dialog.findChild<QSpinBox *>(QStringLiteral("autosave"))->setValue(0);

    const Settings edited = dialog.settings();
    QCOMPARE(edited.uiLanguage, QStringLiteral("zh_CN"));
    QCOMPARE(edited.gridSize, 25);
    QCOMPARE(edited.autosaveMinutes, 0);
    QCOMPARE(original.gridSize, 10);
}

void TestMainWindow::windowLayoutIsRestored()
{
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.findChild<QDockWidget *>(QStringLiteral("messagesDock"))->hide();
        window.close();
    }
    MainWindow reopened;
    reopened.show();
    QVERIFY(QTest::qWaitForWindowExposed(&reopened));
    QVERIFY(!reopened.findChild<QDockWidget *>(QStringLiteral("messagesDock"))->isVisible());
    QVERIFY(reopened.findChild<QDockWidget *>(QStringLiteral("projectDock"))->isVisible());
}

void TestMainWindow::openEditSaveReopen()
{
    const QString example = QStringLiteral(IEC_SOURCE_DIR "/resources/examples/first_steps.xml");
    MainWindow window;
    QString error;
    QVERIFY2(window.openProject(example, &error), qPrintable(error));
    QVERIFY(!window.hasUnsavedChanges());
    QCOMPARE(window.windowTitle(), QStringLiteral("First steps (first_steps.xml)[*] - IEC Studio"));

    // The tree lists the program; activating it opens its ST body in an editor.
    ProjectTreeView &tree = window.projectTree();
    const auto *treeModel = static_cast<const ProjectTreeModel *>(tree.model());
    const QModelIndex main = treeModel->index(0, 0, treeModel->index(0, 0));
    QCOMPARE(main.data().toString(), QStringLiteral("Main (PRG)"));
    Q_EMIT tree.activated(main);
    const iec::model::BodyRef body = *treeModel->bodyRef(main);
    iec::editors::CodeEditor *editor = window.documents().textEditorFor(body);
    QVERIFY(editor);
    QVERIFY(editor->toPlainText().contains(QStringLiteral("Pulse(IN := NOT Pulse.Q, PT := T#500ms);")));

    // Typing reaches the model after the editor's pause (flushed here), and marks the window.
    editor->moveCursor(QTextCursor::End);
    QTest::keyClick(editor, Qt::Key_Return);
    QTest::keyClicks(editor, QStringLiteral("Count := Count;"));
    editor->flushPendingEdit();
    QVERIFY(window.projectModel().body(body)->text().endsWith(QStringLiteral("Count := Count;")));
    QVERIFY(window.hasUnsavedChanges());

    QTemporaryDir dir;
    const QString saved = dir.filePath(QStringLiteral("saved.xml"));
    QVERIFY2(window.saveProject(saved, &error), qPrintable(error));
    QVERIFY(!window.hasUnsavedChanges());
    const auto reread = iec::model::plcopen::readProjectFile(saved);
    QVERIFY(reread.ok);
    QVERIFY(reread.project.types.pous.front().body()->text().endsWith(QStringLiteral("Count := Count;")));

    MainWindow reopened;
    QVERIFY(reopened.openProject(saved, &error));
    QCOMPARE(reopened.projectModel().project().types.pous.front().body()->text(),
        window.projectModel().project().types.pous.front().body()->text());
}

void TestMainWindow::openingAMissingFileKeepsTheProject()
{
    MainWindow window;
    QString error;
    QVERIFY(window.openProject(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/first_steps.xml"), &error));
    const iec::model::Project before = window.projectModel().project();

    QVERIFY(!window.openProject(QStringLiteral("/nonexistent/project.xml"), &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(window.projectModel().project() == before);
    QVERIFY(window.currentFile().endsWith(QStringLiteral("first_steps.xml")));
}

// `iecstudio prog.st`: the text is read into a new untitled project whose main program opens;
// text with an error is refused with it and the project shown stays.
void TestMainWindow::iecTextOpensAsAnUntitledProject()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lamp.st"));
    const QByteArray text = "PROGRAM Main\nVAR\n    Lamp : BOOL;\nEND_VAR\nLamp := NOT Lamp;\nEND_PROGRAM\n";
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write(text) == text.size());
    file.close();
    MainWindow window;
    QString error;
    QVERIFY2(window.openProject(path, &error), qPrintable(error));
    QCOMPARE(window.currentFile(), QString());
    QCOMPARE(window.windowTitle(), QStringLiteral("lamp[*] - IEC Studio"));
    QVERIFY(!window.hasUnsavedChanges());
    const iec::model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QVERIFY(main && main->body());
    QCOMPARE(main->body()->text(), QStringLiteral("Lamp := NOT Lamp;"));
    QCOMPARE(window.documents().tabText(window.documents().currentIndex()), QStringLiteral("Main"));

    const QString broken = dir.filePath(QStringLiteral("broken.st"));
    QFile bad(broken);
    QVERIFY(bad.open(QIODevice::WriteOnly) && bad.write("PROGRAM P\nx := ;\nEND_PROGRAM\n") > 0);
    bad.close();
    const iec::model::Project before = window.projectModel().project();
    QVERIFY(!window.openProject(broken, &error));
    QVERIFY2(error.startsWith(QStringLiteral("broken.st, line 2: ")), qPrintable(error));
    QVERIFY(window.projectModel().project() == before);
    QVERIFY(window.messagesPane().model().rowCount() >= 1);

    // A CoDeSys 2.3 export: .exp, in Windows-1252; its umlauts are kept and a warning says how it
    // was read.
    const QString exported = dir.filePath(QStringLiteral("PLC_PRG.EXP"));
    QFile exp(exported);
    QVERIFY(exp.open(QIODevice::WriteOnly)
        && exp.write("(* @NESTEDCOMMENTS := 'Yes' *)\r\nPROGRAM PLC_PRG\r\nVAR\r\n\tText : STRING := 'St\xF6rung';\r\nEND_VAR\r\n"
                     "(* @END_DECLARATION := '0' *)\r\nText := 'Gr\xFC\xDF';\r\nEND_PROGRAM\r\n") > 0);
    exp.close();
    QVERIFY2(window.openProject(exported, &error), qPrintable(error));
    const iec::model::Pou *plc = window.projectModel().project().findPou(QStringLiteral("PLC_PRG"));
    QVERIFY(plc && plc->body());
    QCOMPARE(plc->body()->text(), QStringLiteral("Text := 'Grüß';"));
    const MessageListModel &messages = window.messagesPane().model();
    QCOMPARE(messages.rowCount(), 1);
    QCOMPARE(messages.message(0).severity, Message::Severity::Warning);
    QCOMPARE(messages.message(0).line, 4);
    QVERIFY2(messages.message(0).text.startsWith(QStringLiteral("The file is not UTF-8")), qPrintable(messages.message(0).text));
}

namespace {

const QString kFirstSteps = QStringLiteral(IEC_SOURCE_DIR "/resources/examples/first_steps.xml");

// A writable copy of the example, so saving and file times are the test's own.
QString copyOfFirstSteps(const QTemporaryDir &dir, const QString &name = QStringLiteral("plant.xml"))
{
    const QString path = dir.filePath(name);
    QFile::remove(path);
    if (!QFile::copy(kFirstSteps, path))
        return {};
    QFile(path).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
    return path;
}

// Ids are assigned by the model while a project is open; files do not store them.
iec::model::Project withoutIds(iec::model::Project project)
{
    for (iec::model::Pou &pou : project.types.pous)
        pou.id = {};
    return project;
}

iec::model::PouId pouNamed(MainWindow &window, const QString &name)
{
    const iec::model::Pou *pou = window.projectModel().project().findPou(name);
    return pou ? pou->id : iec::model::PouId {};
}

} // namespace

void TestMainWindow::treeOperationsUndoOnTheProjectStack()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    QUndoStack &stack = window.undoStacks().projectStack();
    ProjectCommands &commands = window.projectCommands();
    const iec::model::Project opened = window.projectModel().project();

    // Add an ST program through the Add POU core; it calls Main, so renaming Main rewrites it.
    const auto added = commands.addPou({.name = QStringLiteral("Caller"), .language = iec::editors::EditorLanguage::ST});
    QVERIFY(added);
    QVERIFY(window.hasUnsavedChanges());
    QVERIFY(window.isWindowModified());
    window.projectModel().setBodyText({*added, {}, {}}, QStringLiteral("Main();\nx := main.Count; (* Main *)"));

    QVERIFY(commands.rename({pouNamed(window, QStringLiteral("Main")), {}, {}}, QStringLiteral("Blinker")));
    QCOMPARE(window.projectModel().body({*added, {}, {}})->text(),
        QStringLiteral("Blinker();\nx := Blinker.Count; (* Main *)"));
    const iec::model::Project renamed = window.projectModel().project();

    QVERIFY(commands.duplicate({*added, {}, {}}));
    QCOMPARE(window.projectModel().project().types.pous.back().name, QStringLiteral("Caller_1"));
    const iec::model::Project duplicated = window.projectModel().project();

    QVERIFY(commands.remove({pouNamed(window, QStringLiteral("Blinker")), {}, {}}));
    QVERIFY(!window.projectModel().project().findPou(QStringLiteral("Blinker")));
    const iec::model::Project deleted = window.projectModel().project();
    QCOMPARE(stack.count(), 4);

    // Back step by step (the rename restores the name and the text in one step), then forward.
    stack.undo();
    QVERIFY(window.projectModel().project() == duplicated);
    stack.undo();
    QVERIFY(window.projectModel().project() == renamed);
    stack.undo();
    QVERIFY(window.projectModel().body({*added, {}, {}})->text().startsWith(QStringLiteral("Main();")));
    QCOMPARE(window.projectModel().project().findPou(QStringLiteral("Main"))->name, QStringLiteral("Main"));
    stack.redo();
    stack.redo();
    stack.redo();
    QVERIFY(window.projectModel().project() == deleted);

    // Undo down to where the file was opened: the project is unmodified again. The body text set
    // directly on the model (as the editor does while typing) goes with the POU's removal.
    while (stack.canUndo())
        stack.undo();
    QVERIFY(window.projectModel().project() == opened);
    QVERIFY(!window.hasUnsavedChanges());
    QVERIFY(!window.isWindowModified());
}

void TestMainWindow::activeUndoStackFollowsTheDocuments()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    QUndoGroup &group = window.undoGroup();
    // Opening shows the main program, so its stack is active.
    const iec::model::PouId main = pouNamed(window, QStringLiteral("Main"));
    QCOMPARE(group.activeStack(), &window.undoStacks().pouStack(main));
    window.documents().closeAll();
    QCOMPARE(group.activeStack(), &window.undoStacks().projectStack());
    window.documents().openBody({main, {}, {}});
    QCOMPARE(group.activeStack(), &window.undoStacks().pouStack(main));

    // With the window active, the focus decides: the tree means the project.
    window.show();
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.projectTree().setFocus();
    QCOMPARE(group.activeStack(), &window.undoStacks().projectStack());
    window.documents().textEditorFor({main, {}, {}})->setFocus();
    QCOMPARE(group.activeStack(), &window.undoStacks().pouStack(main));

    window.documents().closeAll();
    QCOMPARE(group.activeStack(), &window.undoStacks().projectStack());
}

void TestMainWindow::undoingTypingBackToTheSavedTextIsClean()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    const iec::model::BodyRef main {pouNamed(window, QStringLiteral("Main")), {}, {}};
    window.documents().openBody(main);
    iec::editors::CodeEditor *editor = window.documents().textEditorFor(main);
    editor->moveCursor(QTextCursor::End);
    QTest::keyClicks(editor, QStringLiteral(" x"));
    QVERIFY(window.hasUnsavedChanges());
    QVERIFY(window.isWindowModified());
    while (editor->document()->isUndoAvailable())
        editor->undo();
    QVERIFY(!window.hasUnsavedChanges());
    QVERIFY(!window.isWindowModified());

    // Typing in a tab that is then closed still counts as unsaved, until the project is saved.
    QTest::keyClicks(editor, QStringLiteral(" y"));
    window.documents().closeAll();
    QVERIFY(window.hasUnsavedChanges());
    QTemporaryDir dir;
    QVERIFY(window.saveProject(dir.filePath(QStringLiteral("typed.xml"))));
    QVERIFY(!window.hasUnsavedChanges());
}

void TestMainWindow::treeActionsFollowTheCurrentItem()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    QVERIFY(window.projectCommands().addPou(
        {.name = QStringLiteral("Scale"), .kind = iec::model::PouKind::Function, .returnType = QStringLiteral("INT")}));
    ProjectTreeActions &actions = window.treeActions();
    ProjectTreeView &tree = window.projectTree();
    const auto enabled
        = [&](const char *name) { return window.findChild<QAction *>(QLatin1String(name))->isEnabled(); };

    // Rows: (current key, rename/delete/duplicate enabled, add action/transition enabled).
    const struct {
        QString key;
        bool itemCommands;
        bool partCommands;
    } rows[] = {
        {ProjectTreeModel::folderKey(ProjectTreeModel::Folder::Programs), false, false},
        {ProjectTreeModel::pouKey(pouNamed(window, QStringLiteral("Main"))), true, true},
        {ProjectTreeModel::pouKey(pouNamed(window, QStringLiteral("Scale"))), true, false},
    };
    for (const auto &row : rows) {
        tree.selectKey(row.key);
        QCOMPARE(tree.currentKey(), row.key);
        QVERIFY(enabled("addPouAction"));
        QCOMPARE(enabled("renameAction"), row.itemCommands);
        QCOMPARE(enabled("deleteAction"), row.itemCommands);
        QCOMPARE(enabled("duplicateAction"), row.itemCommands);
        QCOMPARE(enabled("addActionAction"), row.partCommands);
        QCOMPARE(enabled("addTransitionAction"), row.partCommands);
    }

    // Duplicate (no dialog) selects the copy and opens it.
    tree.selectKey(ProjectTreeModel::pouKey(pouNamed(window, QStringLiteral("Main"))));
    actions.duplicateCurrent();
    const iec::model::PouId copy = pouNamed(window, QStringLiteral("Main_1"));
    QVERIFY(copy.isValid());
    QCOMPARE(tree.currentKey(), ProjectTreeModel::pouKey(copy));
    QCOMPARE(window.documents().currentBody(), std::optional(iec::model::BodyRef {copy, {}, {}}));
}

void TestMainWindow::renamingInPlaceIsUndoable()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    auto *tree = static_cast<ProjectTreeModel *>(window.projectTree().model());
    const iec::model::PouId main = pouNamed(window, QStringLiteral("Main"));
    const QModelIndex index = tree->indexForKey(ProjectTreeModel::pouKey(main));
    QVERIFY(tree->flags(index).testFlag(Qt::ItemIsEditable));
    QVERIFY(!tree->flags(tree->indexForKey(ProjectTreeModel::folderKey(ProjectTreeModel::Folder::Programs)))
                 .testFlag(Qt::ItemIsEditable));
    QCOMPARE(index.data(Qt::EditRole).toString(), QStringLiteral("Main")); // without the (PRG) suffix

    tree->setData(index, QStringLiteral(" Blinker "));
    QCoreApplication::processEvents(); // the rename is queued behind the in-place editor's commit
    QCOMPARE(window.projectModel().project().findPou(main)->name, QStringLiteral("Blinker"));
    QCOMPARE(tree->indexForKey(ProjectTreeModel::pouKey(main)).data().toString(), QStringLiteral("Blinker (PRG)"));
    window.undoStacks().projectStack().undo();
    QCOMPARE(window.projectModel().project().findPou(main)->name, QStringLiteral("Main"));
}

void TestMainWindow::ctrlYRedoesToo()
{
    // Issue 13: Ctrl+Y redoes as well as the platform's Redo key.
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    auto *redo = window.findChild<QAction *>(QStringLiteral("redoAction"));
    QVERIFY(redo->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::Key_Y)));
    QVERIFY(redo->shortcuts().contains(QKeySequence(QKeySequence::Redo)));
    window.show();
    QApplication::setActiveWindow(&window);
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.projectTree().setFocus();
    QVERIFY(window.projectCommands().addPou({.name = QStringLiteral("Extra")}));
    window.undoStacks().projectStack().undo();
    QVERIFY(!window.projectModel().project().findPou(QStringLiteral("Extra")));
    QTest::keyClick(&window.projectTree(), Qt::Key_Y, Qt::ControlModifier);
    QVERIFY(window.projectModel().project().findPou(QStringLiteral("Extra")));
}

void TestMainWindow::editUndoWorksOnTypingOrOnTheActiveStack()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    window.documents().closeAll(); // opening showed the main program
    auto *undo = window.findChild<QAction *>(QStringLiteral("undoAction"));
    auto *redo = window.findChild<QAction *>(QStringLiteral("redoAction"));
    QVERIFY(!undo->isEnabled());

    // No document: the project stack, named after its command.
    QVERIFY(window.projectCommands().addPou({.name = QStringLiteral("Extra")}));
    QVERIFY(undo->isEnabled());
    QCOMPARE(undo->text(), QStringLiteral("&Undo Add POU Extra"));
    undo->trigger();
    QVERIFY(!window.projectModel().project().findPou(QStringLiteral("Extra")));
    QCOMPARE(redo->text(), QStringLiteral("&Redo Add POU Extra"));
    redo->trigger();
    QVERIFY(window.projectModel().project().findPou(QStringLiteral("Extra")));

    // A text document: its typing.
    const iec::model::BodyRef main {pouNamed(window, QStringLiteral("Main")), {}, {}};
    window.documents().openBody(main);
    iec::editors::CodeEditor *editor = window.documents().textEditorFor(main);
    const QString text = editor->toPlainText();
    editor->moveCursor(QTextCursor::End);
    QTest::keyClicks(editor, QStringLiteral(" z"));
    QCOMPARE(undo->text(), QStringLiteral("&Undo Typing"));
    QVERIFY(undo->isEnabled());
    while (undo->isEnabled())
        undo->trigger();
    QCOMPARE(editor->toPlainText(), text);
    QVERIFY(window.projectModel().project().findPou(QStringLiteral("Extra"))); // the stack was not touched
}

void TestMainWindow::renameKeepsTypingNotYetPushed()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    const iec::model::PouId main = pouNamed(window, QStringLiteral("Main"));
    window.documents().openBody({main, {}, {}});
    iec::editors::CodeEditor *editor = window.documents().textEditorFor({main, {}, {}});
    editor->moveCursor(QTextCursor::End);
    QTest::keyClick(editor, Qt::Key_Return);
    QTest::keyClicks(editor, QStringLiteral("Main();")); // still waiting for the editor's pause

    QVERIFY(window.projectCommands().rename({main, {}, {}}, QStringLiteral("Blinker")));
    QVERIFY(window.projectModel().body({main, {}, {}})->text().endsWith(QStringLiteral("\nBlinker();")));
    QVERIFY(editor->toPlainText().endsWith(QStringLiteral("\nBlinker();")));
    window.undoStacks().projectStack().undo();
    QVERIFY(window.projectModel().body({main, {}, {}})->text().endsWith(QStringLiteral("\nMain();")));
}

void TestMainWindow::windowMenuListsAndCyclesDocuments()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    const auto added = window.projectCommands().addPou({.name = QStringLiteral("Second")});
    QVERIFY(added);
    window.documents().openBody({pouNamed(window, QStringLiteral("Main")), {}, {}});
    window.documents().openBody({*added, {}, {}});
    auto *menu = window.findChild<WindowMenu *>(QStringLiteral("windowMenu"));
    menu->rebuild();
    QStringList entries;
    for (QAction *action : menu->actions()) {
        if (action->isCheckable())
            entries << action->text() + (action->isChecked() ? QStringLiteral("*") : QString());
    }
    QCOMPARE(entries, (QStringList {QStringLiteral("Main"), QStringLiteral("Second*")}));

    window.documents().activateNext();
    QCOMPARE(window.documents().currentIndex(), 0); // wraps around
    window.documents().activatePrevious();
    QCOMPARE(window.documents().currentIndex(), 1);
    window.documents().closeAll();
    QCOMPARE(window.documents().count(), 0);

    // The toolbar carries the common commands.
    auto *toolBar = window.findChild<QToolBar *>(QStringLiteral("mainToolBar"));
    QVERIFY(toolBar);
    QVERIFY(toolBar->actions().contains(window.findChild<QAction *>(QStringLiteral("undoAction"))));
}

void TestMainWindow::recentFilesKeepOrderAndCap()
{
    QTemporaryDir dir;
    {
        QSettings store;
        for (int number = 1; number <= 10; ++number)
            RecentFiles::add(store, dir.filePath(QStringLiteral("p%1.xml").arg(number)));
        RecentFiles::add(store, dir.filePath(QStringLiteral("p5.xml"))); // again: moves to the front
    }
    QStringList expected;
    for (const int number : {5, 10, 9, 8, 7, 6, 4, 3})
        expected << dir.filePath(QStringLiteral("p%1.xml").arg(number));
    QCOMPARE(RecentFiles::load(QSettings()), expected);
    QCOMPARE(QSettings().value(QStringLiteral("recentFiles")).toStringList(), expected);

    // Opening and saving put the project first.
    const QString copy = copyOfFirstSteps(dir);
    MainWindow window;
    QVERIFY(window.openProject(copy));
    QCOMPARE(RecentFiles::load(QSettings()).first(), copy);
    QCOMPARE(RecentFiles::load(QSettings()).size(), RecentFiles::kMaxCount);
    const QString savedAs = dir.filePath(QStringLiteral("saved-as.xml"));
    QVERIFY(window.saveProject(savedAs));
    QCOMPARE(RecentFiles::load(QSettings()).mid(0, 2), (QStringList {savedAs, copy}));

    // The menu numbers them in that order; choosing one asks to open it.
    auto *menu = window.findChild<RecentFilesMenu *>(QStringLiteral("recentFilesMenu"));
    menu->rebuild();
    QCOMPARE(menu->actions().size(), RecentFiles::kMaxCount);
    QCOMPARE(menu->actions().first()->text(), QStringLiteral("&1 ") + QDir::toNativeSeparators(savedAs));
    QSignalSpy chosen(menu, &RecentFilesMenu::fileChosen);
    menu->actions().at(1)->trigger();
    QCOMPARE(chosen.size(), 1);
    QCOMPARE(chosen.front().front().toString(), copy);
}

void TestMainWindow::recentFileThatIsGoneIsRemoved()
{
    QTemporaryDir dir;
    const QString kept = copyOfFirstSteps(dir);
    const QString gone = dir.filePath(QStringLiteral("gone.xml"));
    {
        QSettings store;
        RecentFiles::add(store, kept);
        RecentFiles::add(store, gone);
    }
    MainWindow window;
    QString error;
    QVERIFY(!window.openRecent(gone, &error));
    QVERIFY(error.contains(QStringLiteral("gone.xml")));
    QCOMPARE(RecentFiles::load(QSettings()), QStringList {kept});
    QVERIFY(window.openRecent(kept, &error));
    QCOMPARE(window.currentFile(), kept);
}

void TestMainWindow::examplesAreListedAndOpenUntitled()
{
    const QList<Example> examples = Examples::list();
    QVERIFY(!examples.isEmpty());
    const auto firstSteps = std::ranges::find(examples, QStringLiteral("First steps"), &Example::title);
    QVERIFY(firstSteps != examples.end());
    QCOMPARE(firstSteps->resourcePath, QStringLiteral(":/examples/first_steps.xml"));

    MainWindow window;
    auto *menu = window.findChild<ExamplesMenu *>(QStringLiteral("examplesMenu"));
    menu->rebuild();
    QCOMPARE(menu->actions().size(), examples.size());
    QSignalSpy chosen(menu, &ExamplesMenu::exampleChosen);
    for (QAction *action : menu->actions()) {
        if (action->text() == firstSteps->title)
            action->trigger();
    }
    QCOMPARE(chosen.size(), 1);
    QCOMPARE(chosen.front().front().toString(), firstSteps->resourcePath);

    QString error;
    QVERIFY2(window.openExample(firstSteps->resourcePath, &error), qPrintable(error));
    QVERIFY(window.currentFile().isEmpty()); // Save asks where to put it
    QVERIFY(!window.hasUnsavedChanges());
    QCOMPARE(window.windowTitle(), QStringLiteral("First steps[*] - IEC Studio"));
    QVERIFY(withoutIds(window.projectModel().project())
        == withoutIds(iec::model::plcopen::readProjectFile(kFirstSteps).project));
}

void TestMainWindow::autosaveWritesARecoveryFileThatReadsBack()
{
    QTemporaryDir dir;
    const QString project = copyOfFirstSteps(dir);
    MainWindow window;
    QVERIFY(window.openProject(project));
    QVERIFY(!window.autosave()); // nothing unsaved, nothing written
    QVERIFY(RecoveryManager::pendingRecoveries().isEmpty());

    QVERIFY(window.projectCommands().addPou({.name = QStringLiteral("Extra")}));
    QVERIFY(window.autosave());
    const QString recoveryFile = window.recovery().recoveryFile();
    QVERIFY(QFileInfo(recoveryFile).fileName().startsWith(QStringLiteral("plant-")));
    const auto reread = iec::model::plcopen::readProjectFile(recoveryFile);
    QVERIFY(reread.ok);
    QVERIFY(withoutIds(reread.project) == withoutIds(window.projectModel().project()));
    QFile source(recoveryFile + QStringLiteral(".source"));
    QVERIFY(source.open(QIODevice::ReadOnly));
    QCOMPARE(QString::fromUtf8(source.readAll()), project);

    // Undoing back to the opened state makes it unnecessary; so does a clean save.
    window.undoStacks().projectStack().undo();
    QVERIFY(!window.autosave());
    QVERIFY(!QFile::exists(recoveryFile));
    window.undoStacks().projectStack().redo();
    QVERIFY(window.autosave());
    QVERIFY(QFile::exists(recoveryFile));
    QVERIFY(window.saveProject(project));
    QVERIFY(!QFile::exists(recoveryFile));
    QVERIFY(!QFile::exists(recoveryFile + QStringLiteral(".source")));
}

void TestMainWindow::autosaveIntervalFollowsTheSettings()
{
    MainWindow window;
    Settings settings = window.settings();
    settings.autosaveMinutes = 3;
    window.applySettings(settings);
    QVERIFY(window.recovery().timer().isActive());
    QCOMPARE(window.recovery().timer().interval(), 3 * 60 * 1000);
    settings.autosaveMinutes = 0;
    window.applySettings(settings);
    QVERIFY(!window.recovery().timer().isActive());
}

void TestMainWindow::crashLeavesARecoveryThatIsOfferedAndRestores()
{
    QTemporaryDir dir;
    const QString project = copyOfFirstSteps(dir);
    iec::model::Project lost;
    QString recoveryFile;
    {
        auto *crashing = new MainWindow;
        QVERIFY(crashing->openProject(project));
        QVERIFY(crashing->projectCommands().addPou({.name = QStringLiteral("Unsaved")}));
        QVERIFY(crashing->autosave());
        lost = crashing->projectModel().project();
        recoveryFile = crashing->recovery().recoveryFile();
        // A crash: the window goes away without closing, so nothing cleans up.
        delete crashing;
    }
    const QList<Recovery> pending = RecoveryManager::pendingRecoveries();
    QCOMPARE(pending.size(), 1);
    QCOMPARE(pending.front().recoveryFile, recoveryFile);
    QCOMPARE(pending.front().projectFile, project);

    MainWindow window;
    QString error;
    QVERIFY2(window.recover(pending.front().recoveryFile, &error), qPrintable(error));
    QVERIFY(withoutIds(window.projectModel().project()) == withoutIds(lost));
    QCOMPARE(window.currentFile(), project);
    QVERIFY(window.hasUnsavedChanges()); // recovered content is not in the project file yet
    QVERIFY(window.isWindowModified());

    QVERIFY(window.saveProject(project));
    QVERIFY(!window.hasUnsavedChanges());
    QVERIFY(RecoveryManager::pendingRecoveries().isEmpty());
    QVERIFY(iec::model::plcopen::readProjectFile(project).project.findPou(QStringLiteral("Unsaved")));
}

void TestMainWindow::recoveryOlderThanItsProjectIsNotOffered()
{
    QTemporaryDir dir;
    const QString project = copyOfFirstSteps(dir);
    {
        auto *crashing = new MainWindow;
        QVERIFY(crashing->openProject(project));
        QVERIFY(crashing->projectCommands().addPou({.name = QStringLiteral("Unsaved")}));
        QVERIFY(crashing->autosave());
        delete crashing;
    }
    QCOMPARE(RecoveryManager::pendingRecoveries().size(), 1);
    // The project was saved later (by another window, say): it holds the newer content.
    QFile file(project);
    QVERIFY(file.open(QIODevice::ReadWrite));
    QVERIFY(file.setFileTime(QDateTime::currentDateTime().addSecs(60), QFileDevice::FileModificationTime));
    file.close();
    QVERIFY(RecoveryManager::pendingRecoveries().isEmpty());
}

void TestMainWindow::declarationsAreAboveThePouBody()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    const iec::model::PouId main = pouNamed(window, QStringLiteral("Main"));
    auto *splitter = qobject_cast<QSplitter *>(window.documents().openBody({main, {}, {}}));
    QVERIFY(splitter);
    QCOMPARE(splitter->orientation(), Qt::Vertical);
    auto *declarations = qobject_cast<iec::editors::DeclarationEditor *>(splitter->widget(0));
    QVERIFY(declarations);
    QCOMPARE(window.documents().declarationEditorFor({main, {}, {}}), declarations);
    QVERIFY(qobject_cast<iec::editors::TextEditorWidget *>(splitter->widget(1)));

    iec::editors::DeclarationTableModel *table = declarations->tableModel();
    QStringList names;
    for (const iec::editors::DeclarationRow &row : table->rows())
        names << row.name;
    QCOMPARE(names, (QStringList {QStringLiteral("Pulse"), QStringLiteral("Blink"), QStringLiteral("Count")}));

    // An edit goes on the POU's stack as one step, and makes the project modified.
    const iec::model::Project opened = window.projectModel().project();
    QVERIFY(table->setData(table->index(2, int(iec::editors::DeclarationColumn::InitialValue)), QStringLiteral("3")));
    QUndoStack &stack = window.undoStacks().pouStack(main);
    QCOMPARE(stack.count(), 1);
    QCOMPARE(window.projectModel().findVariable(main, QStringLiteral("Count"))->initialValue,
        iec::model::Value {iec::model::SimpleValue {QStringLiteral("3")}});
    QVERIFY(window.hasUnsavedChanges());
    stack.undo();
    QVERIFY(window.projectModel().project() == opened);
    QVERIFY(!window.hasUnsavedChanges());

    // A chart's placeholder has the declarations too; its action declares nothing of its own.
    ProjectCommands &commands = window.projectCommands();
    const auto chart = commands.addPou({.name = QStringLiteral("Chart"), .language = iec::editors::EditorLanguage::SFC});
    QVERIFY(chart);
    const auto action = commands.addPouPart(*chart, {.name = QStringLiteral("Fill")});
    QVERIFY(action);
    QVERIFY(qobject_cast<QSplitter *>(window.documents().openBody({*chart, {}, {}})));
    QVERIFY(window.documents().declarationEditorFor({*chart, {}, {}}));
    QVERIFY(qobject_cast<iec::editors::TextEditorWidget *>(window.documents().openBody(*action)));
    QVERIFY(!window.documents().declarationEditorFor(*action));
    QVERIFY(window.documents().textEditorFor(*action));
}

namespace {

int errorCount(MainWindow &window)
{
    return window.messagesPane().model().count(Message::Severity::Error);
}

QStringList messageTexts(MainWindow &window)
{
    QStringList texts;
    const MessageListModel &messages = window.messagesPane().model();
    for (int row = 0; row < messages.rowCount(); ++row)
        texts << messages.message(row).text;
    return texts;
}

} // namespace

void TestMainWindow::createTypeBuildFixSaveCloseReopen()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("plant.xml"));
    QString error;
    {
        MainWindow window;
        window.newProject();
        QVERIFY(window.projectModel().project().types.pous.empty());

        // Add an ST program: it is in the model, in the tree and open in a tab.
        const auto program = window.projectCommands().addPou({.name = QStringLiteral("Plant")});
        QVERIFY(program);
        const iec::model::BodyRef body {*program, {}, {}};
        window.documents().openBody(body);
        iec::editors::CodeEditor *editor = window.documents().textEditorFor(body);
        QVERIFY(editor);

        // Type a body that uses an undeclared name; the model gets the text.
        QTest::keyClicks(editor, QStringLiteral("Level := Level + 1;"));
        editor->flushPendingEdit();
        QCOMPARE(window.projectModel().body(body)->text(), QStringLiteral("Level := Level + 1;"));

        // Build: the diagnostic names the variable, located in the POU.
        window.buildController().build();
        QVERIFY(errorCount(window) > 0);
        QVERIFY2(messageTexts(window).join(QLatin1Char('\n')).contains(QStringLiteral("'Level'")),
            qPrintable(messageTexts(window).join(QLatin1Char('\n'))));

        // Fix it with auto-declare: INT guessed from the arithmetic, one step on the POU's stack.
        const iec::editors::DeclarationRow proposal = window.documents().proposeDeclaration(body, QStringLiteral("Level"));
        QCOMPARE(proposal.type, QStringLiteral("INT"));
        QCOMPARE(proposal.varClass, QStringLiteral("VAR"));
        QUndoStack &stack = window.undoStacks().pouStack(*program);
        const int before = stack.count();
        QVERIFY(window.documents().declareVariable(body, proposal, &error));
        QCOMPARE(stack.count(), before + 1);
        const iec::model::Variable *level = window.projectModel().findVariable(*program, QStringLiteral("Level"));
        QVERIFY(level);
        QCOMPARE(std::get<iec::model::ElementaryType>(level->type.kind).name, QStringLiteral("INT"));
        // The declaration editor above the body shows it at once.
        QCOMPARE(window.documents().declarationEditorFor(body)->tableModel()->rows().back().name,
            QStringLiteral("Level"));
        window.buildController().build();
        QCOMPARE(errorCount(window), 0);

        // Save: the file holds the program, its declaration and its body.
        QVERIFY2(window.saveProject(path, &error), qPrintable(error));
        QVERIFY(!window.hasUnsavedChanges());
        const auto saved = iec::model::plcopen::readProjectFile(path);
        QVERIFY(saved.ok);
        QCOMPARE(saved.project.types.pous.size(), size_t(1));
        QCOMPARE(saved.project.types.pous.front().body()->text(), QStringLiteral("Level := Level + 1;"));
        QCOMPARE(saved.project.types.pous.front().pouInterface->varLists.front().variables.front().name,
            QStringLiteral("Level"));
        QVERIFY(window.close()); // nothing unsaved: no question
    }
    MainWindow reopened;
    QVERIFY2(reopened.openProject(path, &error), qPrintable(error));
    const iec::model::Pou *plant = reopened.projectModel().project().findPou(QStringLiteral("Plant"));
    QVERIFY(plant);
    QCOMPARE(plant->body()->text(), QStringLiteral("Level := Level + 1;"));
    reopened.buildController().build();
    QCOMPARE(errorCount(reopened), 0);
}

void TestMainWindow::dataTypeOpensInATabThatFollowsTheType()
{
    MainWindow window;
    window.newProject();
    QUndoStack &projectStack = window.undoStacks().projectStack();
    iec::model::DataTypeDecl speed;
    speed.name = QStringLiteral("Speed");
    speed.baseType.kind = iec::model::ElementaryType {QStringLiteral("INT")};
    projectStack.push(new iec::model::AddDataTypeCommand(window.projectModel(), speed));

    // Activating the data type node opens its editor in a tab titled with the name.
    ProjectTreeView &tree = window.projectTree();
    const auto *treeModel = static_cast<const ProjectTreeModel *>(tree.model());
    const QModelIndex node = treeModel->indexForKey(QStringLiteral("type:speed"));
    QVERIFY(node.isValid());
    Q_EMIT tree.activated(node);
    DocumentArea &documents = window.documents();
    iec::editors::DataTypeEditor *editor = documents.dataTypeEditorFor(QStringLiteral("Speed"));
    QVERIFY(editor);
    QCOMPARE(documents.currentWidget(), editor);
    QCOMPARE(documents.tabText(documents.currentIndex()), QStringLiteral("Speed"));
    QVERIFY(!documents.currentBody());
    Q_EMIT tree.activated(node); // a second time: the same tab
    QCOMPARE(documents.count(), 1);

    // Its edits go on the project stack; a rename retitles the tab, undo too.
    projectStack.push(iec::model::ChangeDataTypeCommand::rename(
        window.projectModel(), QStringLiteral("Speed"), QStringLiteral("Velocity")));
    QCOMPARE(documents.tabText(documents.indexOf(editor)), QStringLiteral("Velocity"));
    projectStack.undo();
    QCOMPARE(documents.tabText(documents.indexOf(editor)), QStringLiteral("Speed"));

    // Removing the type closes the tab.
    projectStack.push(new iec::model::RemoveDataTypeCommand(window.projectModel(), QStringLiteral("Speed")));
    QCoreApplication::sendPostedEvents(); // the close is queued
    QCOMPARE(documents.count(), 0);
}

void TestMainWindow::undoInTheDeclarationTableUndoesTheTableEdit()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    window.show();
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    const iec::model::BodyRef main {pouNamed(window, QStringLiteral("Main")), {}, {}};
    window.documents().openBody(main);
    iec::editors::CodeEditor *editor = window.documents().textEditorFor(main);
    editor->setFocus();
    QTest::keyClicks(editor, QStringLiteral(" "));

    // The table has the focus: Edit → Undo is the table's last gesture, not the typing.
    iec::editors::DeclarationEditor *declarations = window.documents().declarationEditorFor(main);
    declarations->table()->setFocus();
    iec::editors::DeclarationTableModel *table = declarations->tableModel();
    QVERIFY(table->setData(table->index(2, int(iec::editors::DeclarationColumn::InitialValue)), QStringLiteral("7")));
    QVERIFY(table->setData(table->index(1, int(iec::editors::DeclarationColumn::Comment)), QStringLiteral("lamp")));
    auto *undo = window.findChild<QAction *>(QStringLiteral("undoAction"));
    QVERIFY(undo->isEnabled());
    QVERIFY(undo->text() != QStringLiteral("&Undo Typing"));
    undo->trigger();
    // One gesture, one step: the comment is gone, the initial value stays.
    QVERIFY(!window.projectModel().findVariable(main.pou, QStringLiteral("Blink"))->documentation);
    QCOMPARE(window.projectModel().findVariable(main.pou, QStringLiteral("Count"))->initialValue,
        iec::model::Value {iec::model::SimpleValue {QStringLiteral("7")}});
    undo->trigger();
    QCOMPARE(window.projectModel().findVariable(main.pou, QStringLiteral("Count"))->initialValue,
        iec::model::Value {iec::model::SimpleValue {QStringLiteral("0")}});
    QVERIFY(editor->document()->isUndoAvailable()); // the typing was not touched

    // Back in the body: its typing.
    editor->setFocus();
    QCOMPARE(undo->text(), QStringLiteral("&Undo Typing"));
}

void TestMainWindow::goToDefinitionShowsDeclarationsAndOpensPous()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    const iec::model::PouId mainId = pouNamed(window, QStringLiteral("Main"));
    const iec::model::BodyRef main {mainId, {}, {}};
    const auto helper = window.projectCommands().addPou(
        {.name = QStringLiteral("Helper"), .kind = iec::model::PouKind::Function, .returnType = QStringLiteral("INT")});
    QVERIFY(helper);
    DocumentArea &documents = window.documents();
    documents.openBody(main);

    // A variable: its row in the declaration table.
    QVERIFY(documents.goToDefinition(main, QStringLiteral("count")));
    iec::editors::DeclarationEditor *declarations = documents.declarationEditorFor(main);
    QCOMPARE(declarations->table()->currentIndex().row(), 2);
    // A POU: its tab.
    QVERIFY(documents.goToDefinition(main, QStringLiteral("Helper")));
    QCOMPARE(documents.currentBody(), std::optional<iec::model::BodyRef>({*helper, {}, {}}));
    // A member of a standard FB instance, a keyword: nothing to go to.
    QVERIFY(!documents.goToDefinition(main, QStringLiteral("Pulse.Q")));
    QVERIFY(!documents.goToDefinition(main, QStringLiteral("TON")));

    // F12 in the body goes through the editor's request.
    documents.openBody(main);
    iec::editors::CodeEditor *editor = documents.textEditorFor(main);
    const int at = editor->toPlainText().indexOf(QStringLiteral("Blink"));
    QVERIFY(at >= 0);
    QTextCursor cursor = editor->textCursor();
    cursor.setPosition(at + 1);
    editor->setTextCursor(cursor);
    QTest::keyClick(editor, Qt::Key_F12);
    QCOMPARE(declarations->table()->currentIndex().row(), 1);
}

void TestMainWindow::completionComesFromTheModel()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    const iec::model::PouId main = pouNamed(window, QStringLiteral("Main"));
    window.documents().openBody({main, {}, {}});
    const iec::editors::CompletionProvider *provider
        = window.documents().textEditorFor({main, {}, {}})->completionProvider();
    QVERIFY(provider);
    const auto texts = [](const QList<iec::editors::CompletionItem> &items) {
        QStringList list;
        for (const iec::editors::CompletionItem &item : items)
            list << item.text;
        return list;
    };
    using iec::editors::completionContext;
    using iec::editors::completionItems;
    using iec::editors::TextLanguage;
    // Variables in scope, with their types.
    const auto variables = completionItems(completionContext(u"Co", 2), provider, TextLanguage::ST);
    QVERIFY(texts(variables).contains(QStringLiteral("Count")));
    // Members of a standard FB instance after '.'.
    QCOMPARE(texts(completionItems(completionContext(u"Pulse.", 6), provider, TextLanguage::ST)),
        (QStringList {QStringLiteral("ET"), QStringLiteral("IN"), QStringLiteral("PT"), QStringLiteral("Q")}));
    // User POUs with their parameters, and members of a user FB instance.
    QVERIFY(window.projectCommands().addPou({.name = QStringLiteral("Valve"), .kind = iec::model::PouKind::FunctionBlock}));
    const iec::model::PouId valve = pouNamed(window, QStringLiteral("Valve"));
    iec::model::Interface valveInterface;
    valveInterface.varLists.push_back({.kind = iec::model::VarListKind::Input});
    valveInterface.varLists.back().variables.push_back({.name = QStringLiteral("Open")});
    valveInterface.varLists.push_back({.kind = iec::model::VarListKind::Local});
    valveInterface.varLists.back().variables.push_back({.name = QStringLiteral("Hidden")});
    window.projectModel().setInterface(valve, valveInterface);
    iec::model::Variable v1;
    v1.name = QStringLiteral("V1");
    v1.type.kind = iec::model::DerivedType {.name = QStringLiteral("Valve")};
    window.projectModel().addVariable(main, iec::model::VarListKind::Local, v1);
    const auto pous = completionItems(completionContext(u"Val", 3), provider, TextLanguage::ST);
    QCOMPARE(texts(pous), QStringList {QStringLiteral("Valve")});
    QCOMPARE(pous.front().detail, QStringLiteral("Valve(Open : BOOL)"));
    QCOMPARE(texts(completionItems(completionContext(u"V1.", 3), provider, TextLanguage::ST)),
        QStringList {QStringLiteral("Open")});
    // Keywords and standard functions.
    QVERIFY(texts(completionItems(completionContext(u"END_I", 5), provider, TextLanguage::ST))
                .contains(QStringLiteral("END_IF")));
    QVERIFY(texts(completionItems(completionContext(u"LIM", 3), provider, TextLanguage::ST))
                .contains(QStringLiteral("LIMIT")));
}

void TestMainWindow::autoDeclareGuessesTheType_data()
{
    QTest::addColumn<QString>("body");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("type");
    QTest::newRow("condition") << QStringLiteral("IF Start THEN Count := 1; END_IF;") << QStringLiteral("Start")
                               << QStringLiteral("BOOL");
    QTest::newRow("logic") << QStringLiteral("Blink := Start AND NOT Stop;") << QStringLiteral("Stop")
                           << QStringLiteral("BOOL");
    QTest::newRow("arithmetic") << QStringLiteral("Count := Total * 2;") << QStringLiteral("Total")
                                << QStringLiteral("INT");
    QTest::newRow("time comparison") << QStringLiteral("IF Elapsed > T#5s THEN Blink := TRUE; END_IF;")
                                     << QStringLiteral("Elapsed") << QStringLiteral("TIME");
    QTest::newRow("time assignment") << QStringLiteral("Delay := T#2s;") << QStringLiteral("Delay")
                                     << QStringLiteral("TIME");
    QTest::newRow("real") << QStringLiteral("Ratio := 0.5;") << QStringLiteral("Ratio") << QStringLiteral("REAL");
    QTest::newRow("known variable") << QStringLiteral("Copy := Count;") << QStringLiteral("Copy")
                                    << QStringLiteral("INT");
    QTest::newRow("timer call") << QStringLiteral("T1(IN := Start, PT := T#1s); Blink := T1.Q;")
                                << QStringLiteral("T1") << QStringLiteral("TON");
    QTest::newRow("counter") << QStringLiteral("C1(CU := Start, PV := 5); Count := C1.CV;") << QStringLiteral("C1")
                             << QStringLiteral("CTU");
    QTest::newRow("edge") << QStringLiteral("Edge(CLK := Start);") << QStringLiteral("Edge")
                          << QStringLiteral("R_TRIG");
    QTest::newRow("IL coil") << QStringLiteral("LD Start\nS Motor") << QStringLiteral("Motor")
                             << QStringLiteral("BOOL");
    QTest::newRow("IL arithmetic") << QStringLiteral("LD Count\nADD Delta\nST Count") << QStringLiteral("Delta")
                                   << QStringLiteral("INT");
}

void TestMainWindow::autoDeclareGuessesTheType()
{
    QFETCH(QString, body);
    QFETCH(QString, name);
    QFETCH(QString, type);
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    const iec::model::BodyRef main {pouNamed(window, QStringLiteral("Main")), {}, {}};
    QVERIFY(window.projectModel().setBodyText(main, body));
    QCOMPARE(window.documents().proposeDeclaration(main, name).type, type);
}

// In a diagram, an instance name proposes its box's type (not BOOL), whatever the variable is
// called; a name that is no instance is guessed as before.
void TestMainWindow::autoDeclareInADiagramTakesTheBoxType()
{
    MainWindow window;
    QVERIFY(window.openProject(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/staggered_fans.xml")));
    const iec::model::BodyRef main {pouNamed(window, QStringLiteral("Main")), {}, {}};
    QCOMPARE(window.documents().proposeDeclaration(main, QStringLiteral("Delay2")).type, QStringLiteral("TON"));
    QCOMPARE(window.documents().proposeDeclaration(main, QStringLiteral("running")).type, QStringLiteral("RS"));
    QCOMPARE(window.documents().proposeDeclaration(main, QStringLiteral("Lamp")).type, QStringLiteral("BOOL"));
}

void TestMainWindow::importMergesAndExportWritesTheSelection()
{
    QTemporaryDir dir;
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
    ImportExportActions &files = window.importExport();
    QString error;

    // Export the whole project as IEC text and Main alone as PLCopen XML.
    const QString text = dir.filePath(QStringLiteral("all.st"));
    QVERIFY2(files.exportFile(text, {}, &error), qPrintable(error));
    QFile textFile(text);
    QVERIFY(textFile.open(QIODevice::ReadOnly));
    const QString iec = QString::fromUtf8(textFile.readAll());
    QVERIFY(iec.contains(QStringLiteral("PROGRAM Main")));
    QVERIFY(iec.contains(QStringLiteral("Pulse(IN := NOT Pulse.Q, PT := T#500ms);")));
    QVERIFY(window.projectCommands().addPou({.name = QStringLiteral("Other")}));
    const QString xml = dir.filePath(QStringLiteral("main.xml"));
    QVERIFY2(files.exportFile(xml, {pouNamed(window, QStringLiteral("Main"))}, &error), qPrintable(error));
    const auto exported = iec::model::plcopen::readProjectFile(xml);
    QVERIFY(exported.ok);
    QCOMPARE(exported.project.types.pous.size(), size_t(1));
    QCOMPARE(exported.project.types.pous.front().name, QStringLiteral("Main"));

    // The tree's selection: a POU node stands for its POU.
    ProjectTreeView &tree = window.projectTree();
    tree.selectKey(ProjectTreeModel::pouKey(pouNamed(window, QStringLiteral("Other"))));
    QCOMPARE(files.selectedPous(), std::vector<iec::model::PouId> {pouNamed(window, QStringLiteral("Other"))});
    QVERIFY(files.exportSelectionAction()->isEnabled());

    // Import both into the project: a taken name gets a suffix; one undo step takes it back.
    const iec::model::Project before = window.projectModel().project();
    QVERIFY2(files.importFile(xml, &error), qPrintable(error));
    QVERIFY(window.projectModel().project().findPou(QStringLiteral("Main_1")));
    QVERIFY2(files.importFile(text, &error), qPrintable(error));
    QVERIFY(window.projectModel().project().findPou(QStringLiteral("Main_2")));
    QCOMPARE(window.projectModel().project().findPou(QStringLiteral("Main_2"))->body()->text(),
        window.projectModel().project().findPou(QStringLiteral("Main"))->body()->text());
    QUndoStack &stack = window.undoStacks().projectStack();
    stack.undo();
    stack.undo();
    QVERIFY(window.projectModel().project() == before);

    // A file that is not a project says so and changes nothing.
    const QString junk = dir.filePath(QStringLiteral("junk.xml"));
    QFile junkFile(junk);
    QVERIFY(junkFile.open(QIODevice::WriteOnly));
    junkFile.write("<html/>");
    junkFile.close();
    QVERIFY(!files.importFile(junk, &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(window.projectModel().project() == before);
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
