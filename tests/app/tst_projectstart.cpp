// Starting a project: every template compiles, opening a project shows its main program, and a
// project made from the LD template, given a global variable list and a task with two programs,
// runs online.
#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/globallistcommands.h"
#include "app/mainwindow.h"
#include "app/messagespane.h"
#include "app/newprojectdialog.h"
#include "app/online/onlinecontroller.h"
#include "app/online/watchpane.h"
#include "app/projecttemplates.h"
#include "editors/datatypes/rowtable.h"
#include "editors/declarations/declarationtablemodel.h"
#include "editors/globals/globallisteditor.h"
#include "editors/tasks/configurationeditor.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"
#include "testsettings.h"

#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace iec;
using namespace iec::app;

Q_DECLARE_METATYPE(iec::app::ProjectTemplate)

class TestProjectStart : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void everyTemplateCompiles_data();
    void everyTemplateCompiles();
    void newProjectDialogOffersTheTemplates();
    void openingAProjectShowsItsMainProgram();
    void ladderProjectWithListAndTaskRunsOnline();

private:
    QTemporaryDir m_configHome;
};

void TestProjectStart::initTestCase()
{
    useTestSettings(m_configHome);
}

void TestProjectStart::everyTemplateCompiles_data()
{
    QTest::addColumn<ProjectTemplate>("projectTemplate");
    QTest::addColumn<int>("language");
    QTest::newRow("ST") << ProjectTemplate::ST << int(model::BodyLanguage::ST);
    QTest::newRow("LD") << ProjectTemplate::LD << int(model::BodyLanguage::LD);
    QTest::newRow("FBD") << ProjectTemplate::FBD << int(model::BodyLanguage::FBD);
    QTest::newRow("CFC") << ProjectTemplate::CFC << int(model::BodyLanguage::FBD);
    QTest::newRow("SFC") << ProjectTemplate::SFC << int(model::BodyLanguage::SFC);
    QTest::newRow("IL") << ProjectTemplate::IL << int(model::BodyLanguage::IL);
}

void TestProjectStart::everyTemplateCompiles()
{
    QFETCH(ProjectTemplate, projectTemplate);
    QFETCH(int, language);
    const model::Project project = ProjectTemplates::create(projectTemplate);
    const model::Pou *main = project.findPou(QStringLiteral("Main"));
    QVERIFY(main);
    QCOMPARE(int(main->language()), language);
    QCOMPARE(mainProgramName(project), QStringLiteral("Main"));
    const model::Task &task = project.instances.configurations.at(0).resources.at(0).tasks.at(0);
    QCOMPARE(task.name, QStringLiteral("MainTask"));
    QCOMPARE(task.interval, std::optional(QStringLiteral("T#10ms")));
    const QList<Message> messages = compileMessages(project);
    QVERIFY2(messages.isEmpty(), qPrintable(messages.value(0).text));
    // It is a project any PLCopen tool reads.
    QTemporaryDir dir;
    QString error;
    QVERIFY2(model::plcopen::saveProjectFile(project, dir.filePath(QStringLiteral("t.xml")), &error), qPrintable(error));
    QVERIFY(ProjectTemplates::create(ProjectTemplate::Empty).types.pous.empty());
}

void TestProjectStart::newProjectDialogOffersTheTemplates()
{
    NewProjectDialog dialog;
    QCOMPARE(dialog.chosen(), ProjectTemplate::ST);
    dialog.choose(ProjectTemplate::SFC);
    QCOMPARE(dialog.chosen(), ProjectTemplate::SFC);
    MainWindow window;
    window.newProjectFromTemplate(ProjectTemplate::IL);
    const std::optional<model::BodyRef> current = window.documents().currentBody();
    QVERIFY(current);
    QCOMPARE(window.projectModel().project().findPou(current->pou)->name, QStringLiteral("Main"));
    QVERIFY(!window.hasUnsavedChanges());
}

void TestProjectStart::openingAProjectShowsItsMainProgram()
{
    // The mixing tank's task runs instance Tank of program Main.
    MainWindow window;
    QString error;
    QVERIFY2(window.openExample(QStringLiteral(":/examples/mixing_tank.xml"), &error), qPrintable(error));
    const std::optional<model::BodyRef> current = window.documents().currentBody();
    QVERIFY(current);
    QCOMPARE(window.projectModel().project().findPou(current->pou)->name, QStringLiteral("Main"));
}

void TestProjectStart::ladderProjectWithListAndTaskRunsOnline()
{
    MainWindow window;
    window.newProjectFromTemplate(ProjectTemplate::LD);
    model::ProjectModel &model = window.projectModel();

    // A global variable list IO with the lamp's twin.
    const auto list = window.globalListCommands().add(QStringLiteral("IO"));
    QVERIFY(list);
    auto *listEditor = qobject_cast<editors::GlobalListEditor *>(window.documents().openGlobalList(*list));
    QVERIFY(listEditor);
    listEditor->addRow();
    editors::DeclarationTableModel *rows = listEditor->tableModel();
    QVERIFY(rows->setData(rows->index(0, int(editors::DeclarationColumn::Name)), QStringLiteral("Ticks")));
    QVERIFY(rows->setData(rows->index(0, int(editors::DeclarationColumn::Type)), QStringLiteral("INT")));
    QCOMPARE(listEditor->problemText(), QString());

    // A second program, and a slow task that runs it twice.
    model::Pou counter;
    counter.name = QStringLiteral("Counter");
    counter.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::ST));
    counter.bodies.back().setText(QStringLiteral("IO.Ticks := IO.Ticks + 1;"));
    model.addPou(counter);
    auto *tasks = qobject_cast<editors::ConfigurationEditor *>(window.documents().openConfiguration(QStringLiteral("Config")));
    QVERIFY(tasks);
    tasks->taskTable()->addRow();
    QTableWidget *taskCells = tasks->taskTable()->table();
    taskCells->item(1, int(editors::TaskColumn::Name))->setText(QStringLiteral("Slow"));
    taskCells->item(1, int(editors::TaskColumn::Interval))->setText(QStringLiteral("T#20ms"));
    taskCells->setCurrentCell(1, 0);
    editors::RowTable *programs = tasks->instanceTable();
    for (const char *instance : {"CountA", "CountB"}) {
        programs->addRow();
        const int row = programs->table()->rowCount() - 1;
        programs->table()->item(row, int(editors::InstanceColumn::Program))->setText(QStringLiteral("Counter"));
        programs->table()->item(row, int(editors::InstanceColumn::Name))->setText(QString::fromLatin1(instance));
    }
    QCOMPARE(tasks->problemText(), QString());
    const model::Task &slow = model.project().instances.configurations[0].resources[0].tasks.at(1);
    QCOMPARE(slow.pouInstances.size(), size_t(2));

    // Online: the rung lights the lamp, both counters count in the slow task.
    OnlineController &online = window.online();
    online.setThreaded(false); // every command completes before it returns
    QVERIFY2(online.login(), qPrintable(window.messagesPane().summary()));
    WatchPane &watch = window.watchPane();
    QVERIFY(watch.addVariable(QStringLiteral("Main.Lamp")));
    QVERIFY(watch.addVariable(QStringLiteral("IO.Ticks")));
    online.write(QStringLiteral("Main.Start"), QStringLiteral("TRUE"));
    for (int cycle = 0; cycle < 4; ++cycle)
        online.singleCycle();
    QCOMPARE(watch.model().value(0), QStringLiteral("TRUE"));
    QVERIFY(watch.model().value(1).toInt() >= 2); // two instances each cycle the task runs
    QCOMPARE(watch.model().value(1).toInt() % 2, 0);
    online.logout();
}

QTEST_MAIN(TestProjectStart)
#include "tst_projectstart.moc"
