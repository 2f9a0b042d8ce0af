// The task configuration: rows <-> resources and tasks, the checks as a table (each problem at
// its cell), and the editor driven through its tables, checking the model after undo and redo.
#include "editors/datatypes/rowtable.h"
#include "editors/tasks/configurationeditor.h"
#include "editors/tasks/taskrows.h"
#include "model/projectmodel.h"

#include <QLineEdit>
#include <QListWidget>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <QUndoStack>

using namespace iec::editors;
using namespace iec::model;

Q_DECLARE_METATYPE(iec::model::Configuration)
Q_DECLARE_METATYPE(std::vector<iec::editors::ConfigurationProblem>)

namespace {

Pou program(const QString &name)
{
    Pou pou;
    pou.name = name;
    pou.bodies.push_back(Body::withLanguage(BodyLanguage::ST));
    return pou;
}

Task task(const QString &name, const QString &interval, quint32 priority, std::vector<PouInstance> instances = {})
{
    Task value;
    value.name = name;
    if (!interval.isEmpty())
        value.interval = interval;
    value.priority = priority;
    value.pouInstances = std::move(instances);
    return value;
}

PouInstance instance(const QString &name, const QString &type)
{
    return {.name = name, .typeName = type};
}

Configuration sampleConfiguration()
{
    Configuration configuration;
    configuration.name = QStringLiteral("Plant");
    Resource resource;
    resource.name = QStringLiteral("CPU");
    resource.tasks.push_back(task(QStringLiteral("Fast"), QStringLiteral("T#10ms"), 1, {instance(QStringLiteral("Main"), QStringLiteral("Main"))}));
    resource.tasks.push_back(task(QStringLiteral("Slow"), QStringLiteral("T#100ms"), 5, {instance(QStringLiteral("Log"), QStringLiteral("Logger"))}));
    VarList globals;
    globals.kind = VarListKind::Global;
    Variable alarm;
    alarm.name = QStringLiteral("Alarm");
    globals.variables.push_back(alarm);
    Variable level;
    level.name = QStringLiteral("Level");
    level.type = {ElementaryType {QStringLiteral("INT")}};
    globals.variables.push_back(level);
    resource.globalVars.push_back(globals);
    configuration.resources.push_back(resource);
    return configuration;
}

Project sampleProject()
{
    Project project;
    project.types.pous = {program(QStringLiteral("Main")), program(QStringLiteral("Logger"))};
    project.instances.configurations.push_back(sampleConfiguration());
    return project;
}

ConfigurationProblem problem(int task, int instance, int column, const QString &message)
{
    return {0, task, instance, column, message};
}

void editCell(RowTable &table, int row, int column, const QString &text)
{
    table.table()->item(row, column)->setText(text);
}

} // namespace

class TestTasks : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void rowsAreTheTasksAsText();
    void rowsKeepWhatTheTableDoesNotShow();
    void isoIntervalsShowAsIecTimes();
    void validate_data();
    void validate();
    void watchdogIsKeptInAddData();

    void editingACellIsOneUndoStep();
    void invalidCellIsMarkedAndNothingChanges();
    void programsOfTheCurrentTask();
    void addingTaskAndResource();
    void opensAtTheTaskAndListsTheResourceGlobals();
};

void TestTasks::rowsAreTheTasksAsText()
{
    const Resource resource = sampleConfiguration().resources[0];
    QCOMPARE(taskRows(resource),
        (std::vector<TextRow> {{{QStringLiteral("Fast"), QStringLiteral("T#10ms"), {}, QStringLiteral("1"), {}}, 0},
            {{QStringLiteral("Slow"), QStringLiteral("T#100ms"), {}, QStringLiteral("5"), {}}, 1}}));
    QCOMPARE(instanceRows(resource.tasks[1]), (std::vector<TextRow> {{{QStringLiteral("Log"), QStringLiteral("Logger")}, 0}}));
}

void TestTasks::rowsKeepWhatTheTableDoesNotShow()
{
    const Resource resource = sampleConfiguration().resources[0];
    // The rows swapped, the first one an event task now: the instances travel with their task.
    const std::vector<TextRow> rows {{{QStringLiteral("Slow"), QStringLiteral("T#100ms"), {}, QStringLiteral("5"), {}}, 1},
        {{QStringLiteral("Fast"), {}, QStringLiteral("Alarm"), QStringLiteral("2"), {}}, 0},
        {{QStringLiteral("New"), QStringLiteral("T#1s"), {}, QStringLiteral("x"), {}}, -1}};
    const ResourceResult result = resourceWithTaskRows(resource, rows, 0);
    QCOMPARE(result.resource.tasks.size(), size_t(3));
    QCOMPARE(result.resource.tasks[0].pouInstances, resource.tasks[1].pouInstances);
    QCOMPARE(result.resource.tasks[1].pouInstances, resource.tasks[0].pouInstances);
    QCOMPARE(result.resource.tasks[1].interval, std::nullopt);
    QCOMPARE(result.resource.tasks[1].single, std::optional(QStringLiteral("Alarm")));
    QCOMPARE(result.resource.tasks[1].priority, 2u);
    QVERIFY(result.resource.tasks[2].pouInstances.empty());
    QCOMPARE(result.problems,
        (std::vector<ConfigurationProblem> {problem(2, -1, int(TaskColumn::Priority),
            QStringLiteral("\"x\" is not a priority: use a whole number from 0 (highest) to 65535."))}));
    QCOMPARE(result.resource.globalVars, resource.globalVars);

    const Task moved = taskWithInstanceRows(resource.tasks[0],
        {{{QStringLiteral("Log2"), QStringLiteral("Logger")}, -1}, {{QStringLiteral("Main"), QStringLiteral("Main")}, 0}});
    QCOMPARE(moved.pouInstances, (std::vector<PouInstance> {instance(QStringLiteral("Log2"), QStringLiteral("Logger")),
                                     instance(QStringLiteral("Main"), QStringLiteral("Main"))}));
}

void TestTasks::isoIntervalsShowAsIecTimes()
{
    QCOMPARE(shownTime(QStringLiteral("PT0.01S")), QStringLiteral("T#10ms"));
    QCOMPARE(shownTime(QStringLiteral("PT1M30S")), QStringLiteral("T#1m30s"));
    QCOMPARE(shownTime(QStringLiteral("T#20ms")), QStringLiteral("T#20ms"));
    QCOMPARE(shownTime(QStringLiteral("Pfff")), QStringLiteral("Pfff")); // no duration: shown as it is

    Resource resource = sampleConfiguration().resources[0];
    resource.tasks[0].interval = QStringLiteral("PT0.01S");
    resource.tasks[1].interval = QStringLiteral("PT0.1S");
    std::vector<TextRow> rows = taskRows(resource);
    QCOMPARE(rows[0].cells[int(TaskColumn::Interval)], QStringLiteral("T#10ms"));
    // The priority of the first task changed, the interval of the second: the first keeps the
    // file's text, the second takes the typed one.
    rows[0].cells[int(TaskColumn::Priority)] = QStringLiteral("3");
    rows[1].cells[int(TaskColumn::Interval)] = QStringLiteral("T#200ms");
    const ResourceResult result = resourceWithTaskRows(resource, rows, 0);
    QCOMPARE(result.resource.tasks[0].interval, std::optional(QStringLiteral("PT0.01S")));
    QCOMPARE(result.resource.tasks[0].priority, 3u);
    QCOMPARE(result.resource.tasks[1].interval, std::optional(QStringLiteral("T#200ms")));
}

void TestTasks::validate_data()
{
    QTest::addColumn<Configuration>("configuration");
    QTest::addColumn<std::vector<ConfigurationProblem>>("expected");

    QTest::newRow("valid") << sampleConfiguration() << std::vector<ConfigurationProblem> {};
    Configuration c = sampleConfiguration();
    c.resources[0].tasks[1].interval = QStringLiteral("T#0ms");
    QTest::newRow("interval 0") << c
                                << std::vector {problem(1, -1, int(TaskColumn::Interval),
                                       QStringLiteral("A cyclic task needs an interval above 0; leave it empty for a task "
                                                      "started by its SINGLE variable."))};
    c = sampleConfiguration();
    c.resources[0].tasks[1].interval = QStringLiteral("often");
    QTest::newRow("no time") << c
                             << std::vector {problem(1, -1, int(TaskColumn::Interval),
                                    QStringLiteral("\"often\" is not a time such as T#10ms, T#1s or 20ms."))};
    c = sampleConfiguration();
    c.resources[0].tasks[1].name = QStringLiteral("fast");
    QTest::newRow("duplicate task")
        << c << std::vector {problem(1, -1, int(TaskColumn::Name), QStringLiteral("There is another task named fast."))};
    c = sampleConfiguration();
    c.resources[0].tasks[0].single = QStringLiteral("Level");
    c.resources[0].tasks[0].interval.reset();
    QTest::newRow("single not BOOL")
        << c << std::vector {problem(0, -1, int(TaskColumn::Single),
                    QStringLiteral("There is no global BOOL variable Level in this configuration."))};
    c = sampleConfiguration();
    c.resources[0].tasks[0].single = QStringLiteral("alarm");
    c.resources[0].tasks[0].interval.reset();
    QTest::newRow("single BOOL global") << c << std::vector<ConfigurationProblem> {};
    c.resources[0].tasks[0].interval = QStringLiteral("T#10ms");
    QTest::newRow("single and interval")
        << c << std::vector {problem(0, -1, int(TaskColumn::Single),
                    QStringLiteral("A task runs either every interval or when its SINGLE variable becomes TRUE: clear "
                                   "the interval or the SINGLE variable."))};
    c = sampleConfiguration();
    c.resources[0].tasks[1].pouInstances[0].typeName = QStringLiteral("Missing");
    QTest::newRow("unknown program")
        << c << std::vector {problem(1, 0, int(InstanceColumn::Program), QStringLiteral("There is no program called Missing."))};
    c = sampleConfiguration();
    c.resources[0].tasks[1].pouInstances[0].name = QStringLiteral("Main");
    QTest::newRow("duplicate instance")
        << c << std::vector {problem(1, 0, int(InstanceColumn::Name), QStringLiteral("There is another program instance named Main."))};
    c = sampleConfiguration();
    setTaskWatchdog(c.resources[0].tasks[0], QStringLiteral("T#0s"));
    QTest::newRow("watchdog 0") << c
                                << std::vector {problem(0, -1, int(TaskColumn::Watchdog),
                                       QStringLiteral("A watchdog time must be above 0; leave it empty for none."))};
    c = sampleConfiguration();
    c.resources.push_back(c.resources[0]);
    c.resources[1].tasks.clear();
    QTest::newRow("duplicate resource")
        << c << std::vector {ConfigurationProblem {1, -1, -1, 0, QStringLiteral("There is another resource named CPU.")}};
    c = sampleConfiguration();
    c.resources[0].tasks[0].name = QStringLiteral("2fast");
    QTest::newRow("task name no identifier")
        << c << std::vector {problem(0, -1, int(TaskColumn::Name),
                    QStringLiteral("\"2fast\" is not a valid name: use letters, digits and single underscores."))};
}

void TestTasks::validate()
{
    QFETCH(Configuration, configuration);
    QFETCH(std::vector<ConfigurationProblem>, expected);
    QCOMPARE(validateConfiguration(configuration, sampleProject()), expected);
}

void TestTasks::watchdogIsKeptInAddData()
{
    Task value = task(QStringLiteral("T"), QStringLiteral("T#10ms"), 0);
    setTaskWatchdog(value, QStringLiteral("T#50ms"));
    QCOMPARE(taskWatchdog(value), QStringLiteral("T#50ms"));
    QCOMPARE(value.addData.size(), size_t(1));
    QCOMPARE(value.addData[0].name, QString::fromLatin1(kWatchdogAddDataName));
    QCOMPARE(value.addData[0].content, QStringLiteral("<watchdog time=\"T#50ms\"/>"));
    setTaskWatchdog(value, {});
    QVERIFY(value.addData.empty());
}

void TestTasks::editingACellIsOneUndoStep()
{
    ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    ConfigurationEditor editor(model, QStringLiteral("Plant"), stack);
    const Instances before = model.project().instances;
    editCell(*editor.taskTable(), 1, int(TaskColumn::Interval), QStringLiteral("T#50ms"));
    QCOMPARE(editor.problemText(), QString());
    QCOMPARE(stack.count(), 1);
    Instances after = before;
    after.configurations[0].resources[0].tasks[1].interval = QStringLiteral("T#50ms");
    QCOMPARE(model.project().instances, after);
    stack.undo();
    QCOMPARE(model.project().instances, before);
    QCOMPARE(editor.taskTable()->table()->item(1, int(TaskColumn::Interval))->text(), QStringLiteral("T#100ms"));
    stack.redo();
    QCOMPARE(model.project().instances, after);
}

void TestTasks::invalidCellIsMarkedAndNothingChanges()
{
    ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    ConfigurationEditor editor(model, QStringLiteral("Plant"), stack);
    const Instances before = model.project().instances;
    editCell(*editor.taskTable(), 0, int(TaskColumn::Interval), QStringLiteral("T#0ms"));
    QCOMPARE(stack.count(), 0);
    QCOMPARE(model.project().instances, before);
    const QTableWidgetItem *cell = editor.taskTable()->table()->item(0, int(TaskColumn::Interval));
    QCOMPARE(cell->toolTip(), QStringLiteral("A cyclic task needs an interval above 0; leave it empty for a task started by its SINGLE variable."));
    QVERIFY(cell->background().style() != Qt::NoBrush);
    // Fixing it applies the table, and the mark goes.
    editCell(*editor.taskTable(), 0, int(TaskColumn::Interval), QStringLiteral("20ms"));
    QCOMPARE(stack.count(), 1);
    QCOMPARE(model.project().instances.configurations[0].resources[0].tasks[0].interval, std::optional(QStringLiteral("20ms")));
    QCOMPARE(editor.taskTable()->table()->item(0, int(TaskColumn::Interval))->toolTip(), QString());

    // The resource name has its message below the field.
    editor.resourceNameEdit()->setText(QStringLiteral("1CPU"));
    Q_EMIT editor.resourceNameEdit()->editingFinished();
    QCOMPARE(stack.count(), 1);
    QVERIFY(editor.problemText().contains(QStringLiteral("\"1CPU\" is not a valid name")));
}

void TestTasks::programsOfTheCurrentTask()
{
    ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    ConfigurationEditor editor(model, QStringLiteral("Plant"), stack);
    editor.taskTable()->table()->setCurrentCell(1, 0);
    RowTable *instances = editor.instanceTable();
    QCOMPARE(instances->rows().size(), size_t(1));
    QCOMPARE(instances->rows()[0].cells, (QStringList {QStringLiteral("Log"), QStringLiteral("Logger")}));
    // A second program in the slow task; the new row proposes a free instance name.
    instances->table()->setCurrentCell(0, 0);
    instances->addRow();
    QCOMPARE(stack.count(), 1);
    const Task &slow = model.project().instances.configurations[0].resources[0].tasks[1];
    QCOMPARE(slow.pouInstances.size(), size_t(2));
    QCOMPARE(slow.pouInstances[1], instance(QStringLiteral("Main_1"), QStringLiteral("Main")));
    // An unknown program is marked at its cell.
    editCell(*instances, 1, int(InstanceColumn::Program), QStringLiteral("Nothing"));
    QCOMPARE(stack.count(), 1);
    QCOMPARE(instances->table()->item(1, int(InstanceColumn::Program))->toolTip(), QStringLiteral("There is no program called Nothing."));
}

void TestTasks::addingTaskAndResource()
{
    ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    ConfigurationEditor editor(model, QStringLiteral("Plant"), stack);
    editor.taskTable()->addRow();
    QCOMPARE(stack.count(), 1);
    const Resource &resource = model.project().instances.configurations[0].resources[0];
    QCOMPARE(resource.tasks.size(), size_t(3));
    // The new row follows the current one (the first).
    QCOMPARE(resource.tasks[1].name, QStringLiteral("Task1"));
    QCOMPARE(resource.tasks[1].interval, std::optional(QStringLiteral("T#10ms")));
    editor.addResource();
    QCOMPARE(stack.count(), 2);
    QCOMPARE(model.project().instances.configurations[0].resources.size(), size_t(2));
    QCOMPARE(editor.currentResource(), 1);
    QCOMPARE(editor.resourceNameEdit()->text(), QStringLiteral("Resource1"));
    QCOMPARE(editor.taskTable()->rows().size(), size_t(0));
    editor.removeCurrentResource();
    QCOMPARE(model.project().instances.configurations[0].resources.size(), size_t(1));
    stack.undo();
    stack.undo();
    stack.undo();
    QCOMPARE(model.project().instances, sampleProject().instances);
}

void TestTasks::opensAtTheTaskAndListsTheResourceGlobals()
{
    ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    ConfigurationEditor editor(model, QStringLiteral("Plant"), stack);
    editor.showTask(QStringLiteral("CPU"), QStringLiteral("slow"));
    QCOMPARE(editor.currentTask(), 1);
    QCOMPARE(editor.globalListView()->count(), 1);
    QCOMPARE(editor.globalListView()->item(0)->text(), QStringLiteral("CPU"));
    QSignalSpy opened(&editor, &ConfigurationEditor::openGlobalListRequested);
    Q_EMIT editor.globalListView()->itemActivated(editor.globalListView()->item(0));
    QCOMPARE(opened.count(), 1);
    QCOMPARE(opened[0][0].value<GlobalListRef>(), (GlobalListRef {QStringLiteral("Plant"), QStringLiteral("CPU"), {}}));
    QSignalSpy removed(&editor, &ConfigurationEditor::configurationRemoved);
    model.setInstances({});
    QCOMPARE(removed.count(), 1);
}

QTEST_MAIN(TestTasks)
#include "tst_tasks.moc"
