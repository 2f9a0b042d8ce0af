// Global variable lists and configurations in the window: the tree's list commands (add, rename,
// duplicate, delete) as undo steps, lists and configurations opened from the tree, tabs that
// follow renames and close on delete, a global renamed in its list renaming its uses, and the
// compiler accepting `List.Variable` for what the editors made.
#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/globallistcommands.h"
#include "app/mainwindow.h"
#include "app/messagespane.h"
#include "app/projecttreeactions.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "app/undostacks.h"
#include "editors/datatypes/rowtable.h"
#include "editors/declarations/declarationtablemodel.h"
#include "editors/globals/globallisteditor.h"
#include "editors/tasks/configurationeditor.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"
#include "testsettings.h"

#include <QAction>
#include <QSettings>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace iec;
using namespace iec::app;
using editors::GlobalListRef;

namespace {

const char *const kSource = R"(PROGRAM Main
VAR
  Count : INT;
END_VAR
Count := Count + 1;
IO.Valve := Count > 3;
END_PROGRAM
PROGRAM Logger
END_PROGRAM
CONFIGURATION Config
  RESOURCE Resource ON PLC
    VAR_GLOBAL
      Valve : BOOL;
    END_VAR
    TASK MainTask(INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM Main WITH MainTask : Main;
  END_RESOURCE
END_CONFIGURATION
)";

model::Project sampleProject()
{
    model::Project project = interp::frontend::readIecText(QString::fromUtf8(kSource), QStringLiteral("Test")).project;
    // The resource's list is CODESYS's global variable list IO.
    project.instances.configurations[0].resources[0].globalVars[0].name = QStringLiteral("IO");
    return project;
}

const GlobalListRef kIo {QStringLiteral("Config"), QStringLiteral("Resource"), QStringLiteral("IO")};

QStringList listNames(const model::ProjectModel &model)
{
    QStringList names;
    for (const GlobalListRef &list : editors::globalLists(model.project().instances))
        names << list.displayName();
    return names;
}

} // namespace

class TestInstanceDocuments : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void listCommandsAreUndoSteps();
    void listNamesAreChecked_data();
    void listNamesAreChecked();
    void addingAListToAProjectWithoutConfigurationKeepsItRunning();
    void treeOpensListsAndConfigurations();
    void taskConfigurationIsMadeWhenThereIsNone();
    void listTabFollowsRenameAndClosesOnDelete();
    void renamingAGlobalRenamesItsUses();
    void taskWithTwoProgramsCompiles();

private:
    QTemporaryDir m_configHome;
};

void TestInstanceDocuments::initTestCase()
{
    useTestSettings(m_configHome);
}

void TestInstanceDocuments::listCommandsAreUndoSteps()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    GlobalListCommands commands(model, stack);
    const model::Instances before = model.project().instances;

    const auto added = commands.add(QStringLiteral("HMI"));
    QVERIFY(added);
    QCOMPARE(*added, (GlobalListRef {QStringLiteral("Config"), QStringLiteral("Resource"), QStringLiteral("HMI")}));
    const auto renamed = commands.rename(*added, QStringLiteral("Panel"));
    QVERIFY(renamed);
    const auto copy = commands.duplicate(kIo);
    QVERIFY(copy);
    QCOMPARE(copy->name, QStringLiteral("IO_1"));
    QCOMPARE(listNames(model), (QStringList {QStringLiteral("IO"), QStringLiteral("IO_1"), QStringLiteral("Panel")}));
    QVERIFY(commands.remove(kIo));
    QCOMPARE(listNames(model), (QStringList {QStringLiteral("IO_1"), QStringLiteral("Panel")}));
    QCOMPARE(stack.count(), 4);
    QCOMPARE(stack.undoText(), QStringLiteral("Delete global variable list IO"));
    for (int step = 0; step < 4; ++step)
        stack.undo();
    QCOMPARE(model.project().instances, before);
    for (int step = 0; step < 4; ++step)
        stack.redo();
    QCOMPARE(listNames(model), (QStringList {QStringLiteral("IO_1"), QStringLiteral("Panel")}));
}

void TestInstanceDocuments::listNamesAreChecked_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("error");
    QTest::newRow("taken") << QStringLiteral("io") << QStringLiteral("A global variable list named \"io\" exists already.");
    QTest::newRow("a POU") << QStringLiteral("Main") << QStringLiteral("A POU or data type named \"Main\" exists already.");
    QTest::newRow("keyword") << QStringLiteral("VAR") << QStringLiteral("\"VAR\" is a reserved word of IEC 61131-3.");
    QTest::newRow("dot") << QStringLiteral("IO.X")
                         << QStringLiteral("\"IO.X\" is not an IEC identifier: use letters, digits and single "
                                           "underscores, starting with a letter or an underscore and not ending with "
                                           "an underscore.");
}

void TestInstanceDocuments::listNamesAreChecked()
{
    QFETCH(QString, name);
    QFETCH(QString, error);
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    GlobalListCommands commands(model, stack);
    QString message;
    QVERIFY(!commands.add(name, &message));
    QCOMPARE(message, error);
    QCOMPARE(stack.count(), 0);
}

void TestInstanceDocuments::addingAListToAProjectWithoutConfigurationKeepsItRunning()
{
    model::Project project = sampleProject();
    project.instances = {};
    model::ProjectModel model;
    model.reset(project);
    QUndoStack stack;
    GlobalListCommands commands(model, stack);
    const auto added = commands.add(QStringLiteral("GVL"));
    QVERIFY(added);
    QCOMPARE(stack.count(), 1);
    const model::Task &task = model.project().instances.configurations.at(0).resources.at(0).tasks.at(0);
    QCOMPARE(task.pouInstances.at(0).typeName, QStringLiteral("Main"));
    // The program that ran alone runs in the explicit task, and IO.Valve is a variable of the new list.
    QVERIFY(commands.rename(*added, QStringLiteral("IO")));
    model::Interface declarations;
    model::VarList globals;
    globals.kind = model::VarListKind::Global;
    globals.variables.push_back({.name = QStringLiteral("Valve")});
    declarations.varLists.push_back(globals);
    model.setInstances(*editors::withGlobalListDeclarations(
        model.project().instances, {added->configuration, added->resource, QStringLiteral("IO")}, declarations));
    const QList<Message> messages = compileMessages(model.project());
    QVERIFY2(messages.isEmpty(), qPrintable(messages.value(0).text));
}

void TestInstanceDocuments::treeOpensListsAndConfigurations()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    ProjectTreeView &tree = window.projectTree();
    auto *treeModel = qobject_cast<ProjectTreeModel *>(tree.model());
    const QModelIndex list = treeModel->indexForKey(ProjectTreeModel::globalListKey(kIo));
    QVERIFY(list.isValid());
    QCOMPARE(list.data().toString(), QStringLiteral("IO"));
    Q_EMIT tree.activated(list);
    auto *listEditor = qobject_cast<editors::GlobalListEditor *>(window.documents().currentWidget());
    QVERIFY(listEditor);
    QCOMPARE(listEditor->tableModel()->rows().at(0).name, QStringLiteral("Valve"));

    const QModelIndex task = treeModel->indexForKey(QStringLiteral("task:Config.Resource.MainTask"));
    QVERIFY(task.isValid());
    Q_EMIT tree.activated(task);
    auto *configuration = qobject_cast<editors::ConfigurationEditor *>(window.documents().currentWidget());
    QVERIFY(configuration);
    QCOMPARE(configuration->currentTask(), 0);
    QCOMPARE(configuration->instanceTable()->rows().at(0).cells.at(1), QStringLiteral("Main"));
    // Its edits are steps on the project's stack.
    configuration->taskTable()->table()->item(0, int(editors::TaskColumn::Interval))->setText(QStringLiteral("T#20ms"));
    QCOMPARE(window.undoStacks().projectStack().count(), 1);
    QCOMPARE(window.projectModel().project().instances.configurations[0].resources[0].tasks[0].interval,
        std::optional(QStringLiteral("T#20ms")));
}

void TestInstanceDocuments::taskConfigurationIsMadeWhenThereIsNone()
{
    MainWindow window;
    model::Project project = sampleProject();
    project.instances = {};
    window.projectModel().reset(project);
    QAction *action = window.treeActions().taskConfigurationAction();
    QVERIFY(action->isEnabled());
    action->trigger();
    auto *editor = qobject_cast<editors::ConfigurationEditor *>(window.documents().currentWidget());
    QVERIFY(editor);
    QCOMPARE(editor->configuration(), QStringLiteral("Config"));
    QCOMPARE(editor->instanceTable()->rows().at(0).cells, (QStringList {QStringLiteral("Main"), QStringLiteral("Main")}));
    QUndoStack &stack = window.undoStacks().projectStack();
    QCOMPARE(stack.count(), 1);
    QCOMPARE(stack.undoText(), QStringLiteral("Create task configuration Config"));
    // Shown again, the configuration that exists opens: no second step.
    action->trigger();
    QCOMPARE(stack.count(), 1);
    stack.undo();
    QCOMPARE(window.projectModel().project().instances, model::Instances {});
}

void TestInstanceDocuments::listTabFollowsRenameAndClosesOnDelete()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    DocumentArea &documents = window.documents();
    QVERIFY(documents.openGlobalList(kIo));
    const int tab = documents.currentIndex();
    QCOMPARE(documents.tabText(tab), QStringLiteral("IO"));
    QVERIFY(window.globalListCommands().rename(kIo, QStringLiteral("Plant")));
    QCOMPARE(documents.tabText(tab), QStringLiteral("Plant"));
    window.undoStacks().projectStack().undo();
    QCOMPARE(documents.tabText(tab), QStringLiteral("IO"));
    const int tabs = documents.count();
    QVERIFY(window.globalListCommands().remove(kIo));
    QTRY_COMPARE(documents.count(), tabs - 1); // closed after the signal that reported it
}

void TestInstanceDocuments::renamingAGlobalRenamesItsUses()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    auto *editor = qobject_cast<editors::GlobalListEditor *>(window.documents().openGlobalList(kIo));
    QVERIFY(editor);
    editors::DeclarationTableModel *table = editor->tableModel();
    QVERIFY(table->setData(table->index(0, int(editors::DeclarationColumn::Name)), QStringLiteral("Gate")));
    QCOMPARE(editor->problemText(), QString());
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QVERIFY(main->body()->text().contains(QStringLiteral("IO.Gate := Count > 3;")));
    QCOMPARE(window.undoStacks().projectStack().count(), 1);
    window.undoStacks().projectStack().undo();
    QVERIFY(window.projectModel().project().findPou(QStringLiteral("Main"))->body()->text().contains(QStringLiteral("IO.Valve")));
}

void TestInstanceDocuments::taskWithTwoProgramsCompiles()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    auto *editor = qobject_cast<editors::ConfigurationEditor *>(window.documents().openConfiguration(QStringLiteral("Config")));
    QVERIFY(editor);
    editor->taskTable()->addRow();
    QCOMPARE(editor->problemText(), QString());
    editor->taskTable()->table()->setCurrentCell(1, 0);
    editors::RowTable *instances = editor->instanceTable();
    instances->addRow();
    instances->table()->item(0, int(editors::InstanceColumn::Program))->setText(QStringLiteral("Logger"));
    instances->table()->item(0, int(editors::InstanceColumn::Name))->setText(QStringLiteral("Log"));
    instances->addRow();
    QCOMPARE(editor->problemText(), QString());
    const model::Task &added = window.projectModel().project().instances.configurations[0].resources[0].tasks.at(1);
    QCOMPARE(added.pouInstances.size(), size_t(2));
    QCOMPARE(added.pouInstances[0].typeName, QStringLiteral("Logger"));
    QVERIFY(window.buildController().build());
}

QTEST_MAIN(TestInstanceDocuments)
#include "tst_instancedocuments.moc"
