#include "app/documentarea.h"
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
#include "editors/declarations/declarationeditor.h"
#include "editors/declarations/declarationtablemodel.h"
#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "model/plcopen/reader.h"
#include "model/projectmodel.h"

#include <QComboBox>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QSplitter>
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
    void treeOperationsUndoOnTheProjectStack();
    void activeUndoStackFollowsTheDocuments();
    void undoingTypingBackToTheSavedTextIsClean();
    void treeActionsFollowTheCurrentItem();
    void renamingInPlaceIsUndoable();
    void editUndoWorksOnTypingOrOnTheActiveStack();
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
    const auto added = commands.addPou({.name = QStringLiteral("Caller"), .language = iec::model::BodyLanguage::ST});
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
    QCOMPARE(group.activeStack(), &window.undoStacks().projectStack());

    const iec::model::PouId main = pouNamed(window, QStringLiteral("Main"));
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

void TestMainWindow::editUndoWorksOnTypingOrOnTheActiveStack()
{
    MainWindow window;
    QVERIFY(window.openProject(kFirstSteps));
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
    const auto chart = commands.addPou({.name = QStringLiteral("Chart"), .language = iec::model::BodyLanguage::SFC});
    QVERIFY(chart);
    const auto action = commands.addPouPart(*chart, {.name = QStringLiteral("Fill")});
    QVERIFY(action);
    QVERIFY(qobject_cast<QSplitter *>(window.documents().openBody({*chart, {}, {}})));
    QVERIFY(window.documents().declarationEditorFor({*chart, {}, {}}));
    QVERIFY(qobject_cast<iec::editors::TextEditorWidget *>(window.documents().openBody(*action)));
    QVERIFY(!window.documents().declarationEditorFor(*action));
    QVERIFY(window.documents().textEditorFor(*action));
}

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
