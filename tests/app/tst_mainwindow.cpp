#include "app/mainwindow.h"
#include "app/settingsdialog.h"

#include <QComboBox>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include "app/documentarea.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "editors/text/codeeditor.h"
#include "model/plcopen/reader.h"
#include "model/projectmodel.h"

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
}

void TestMainWindow::init()
{
    QSettings store;
    store.clear();
    store.setValue(QStringLiteral("ui/language"), QStringLiteral("en"));
}

void TestMainWindow::opensWithMenusAndDocks()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));

    QCOMPARE(menuTitles(window), (QStringList{QStringLiteral("&File"), QStringLiteral("&Edit"),
                                              QStringLiteral("&View"), QStringLiteral("&Project"),
                                              QStringLiteral("&Online"), QStringLiteral("&Help")}));
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
    QCOMPARE(window.windowTitle(), QStringLiteral("first_steps.xml[*] - IEC Studio"));

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

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
