// What counts as a rename of variables, struct members and globals (model/undo/variablerename).
#include "model/projectmodel.h"
#include "model/undo/instancecommands.h"
#include "model/undo/variablerename.h"

#include <QTest>
#include <QUndoStack>

using namespace iec::model;

Q_DECLARE_METATYPE(std::vector<iec::model::VariableRename>)
Q_DECLARE_METATYPE(iec::model::DataType)

class TestRenameVariable : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void renamedVariablesOfInterfaces_data();
    void renamedVariablesOfInterfaces();
    void renamedMembersOfStructs_data();
    void renamedMembersOfStructs();
    void findsGlobals_data();
    void findsGlobals();
    void globalRenameInInstances();
    void globalRenameRedoUndoRedo();
};

namespace {

Variable variable(const QString &name, const QString &type = QStringLiteral("INT"))
{
    Variable v;
    v.name = name;
    v.type.kind = ElementaryType {.name = type};
    return v;
}

VarList list(VarListKind kind, std::vector<Variable> variables)
{
    return VarList {.kind = kind, .variables = std::move(variables)};
}

// VAR a, b END_VAR VAR_INPUT c END_VAR
std::vector<VarList> abc()
{
    return {list(VarListKind::Local, {variable(QStringLiteral("a")), variable(QStringLiteral("b"))}),
        list(VarListKind::Input, {variable(QStringLiteral("c"), QStringLiteral("BOOL"))})};
}

DataType structOf(std::vector<Variable> members)
{
    return DataType {StructType {.members = std::move(members)}};
}

// Config: VAR_GLOBAL Alarm; resource Res: VAR_GLOBAL Level, Alarm (hidden by the first);
// task Fast started by Alarm, task Slow by Level.
Instances sampleInstances()
{
    Resource resource;
    resource.name = QStringLiteral("Res");
    resource.globalVars.push_back(
        list(VarListKind::Global, {variable(QStringLiteral("Level")), variable(QStringLiteral("Alarm"))}));
    Task fast;
    fast.name = QStringLiteral("Fast");
    fast.single = QStringLiteral("ALARM");
    Task slow;
    slow.name = QStringLiteral("Slow");
    slow.single = QStringLiteral("Level");
    resource.tasks = {fast, slow};
    Configuration configuration;
    configuration.name = QStringLiteral("Config");
    configuration.globalVars.push_back(list(VarListKind::Global, {variable(QStringLiteral("Alarm"), QStringLiteral("BOOL"))}));
    configuration.resources.push_back(resource);
    return Instances {.configurations = {configuration}};
}

} // namespace

void TestRenameVariable::renamedVariablesOfInterfaces_data()
{
    QTest::addColumn<int>("change");
    QTest::addColumn<std::vector<VariableRename>>("expected");
    QTest::newRow("nothing changed") << 0 << std::vector<VariableRename> {};
    QTest::newRow("one renamed") << 1 << std::vector<VariableRename> {{QStringLiteral("b"), QStringLiteral("Speed")}};
    QTest::newRow("case only") << 2 << std::vector<VariableRename> {{QStringLiteral("a"), QStringLiteral("A")}};
    QTest::newRow("renamed and retyped") << 3 << std::vector<VariableRename> {{QStringLiteral("c"), QStringLiteral("d")}};
    QTest::newRow("two swapped") << 4
                                 << std::vector<VariableRename> {{QStringLiteral("a"), QStringLiteral("b")},
                                        {QStringLiteral("b"), QStringLiteral("a")}};
    QTest::newRow("added: no rename") << 5 << std::vector<VariableRename> {};
    QTest::newRow("removed: no rename") << 6 << std::vector<VariableRename> {};
    QTest::newRow("moved to another kind: no rename") << 7 << std::vector<VariableRename> {};
}

void TestRenameVariable::renamedVariablesOfInterfaces()
{
    QFETCH(int, change);
    QFETCH(std::vector<VariableRename>, expected);
    const std::vector<VarList> before = abc();
    std::vector<VarList> after = before;
    switch (change) {
    case 1:
        after[0].variables[1].name = QStringLiteral("Speed");
        break;
    case 2:
        after[0].variables[0].name = QStringLiteral("A");
        break;
    case 3:
        after[1].variables[0] = variable(QStringLiteral("d"), QStringLiteral("REAL"));
        break;
    case 4:
        std::swap(after[0].variables[0].name, after[0].variables[1].name);
        break;
    case 5:
        after[0].variables.push_back(variable(QStringLiteral("e")));
        break;
    case 6:
        after[0].variables.pop_back();
        break;
    case 7:
        after[1].kind = VarListKind::Output;
        after[1].variables[0].name = QStringLiteral("d");
        break;
    default:
        break;
    }
    QCOMPARE(renamedVariables(before, after), expected);
    QCOMPARE(renamedVariables(std::optional<Interface>(Interface {.varLists = before}),
                 std::optional<Interface>(Interface {.varLists = after})),
        expected);
}

void TestRenameVariable::renamedMembersOfStructs_data()
{
    QTest::addColumn<DataType>("after");
    QTest::addColumn<std::vector<VariableRename>>("expected");
    QTest::newRow("member renamed")
        << structOf({variable(QStringLiteral("X")), variable(QStringLiteral("PosY"))})
        << std::vector<VariableRename> {{QStringLiteral("Y"), QStringLiteral("PosY")}};
    QTest::newRow("member added") << structOf(
        {variable(QStringLiteral("X")), variable(QStringLiteral("Y")), variable(QStringLiteral("Z"))})
                                  << std::vector<VariableRename> {};
    QTest::newRow("no longer a struct") << DataType {ElementaryType {.name = QStringLiteral("INT")}}
                                        << std::vector<VariableRename> {};
}

void TestRenameVariable::renamedMembersOfStructs()
{
    QFETCH(DataType, after);
    QFETCH(std::vector<VariableRename>, expected);
    QCOMPARE(renamedMembers(structOf({variable(QStringLiteral("X")), variable(QStringLiteral("Y"))}), after), expected);
}

void TestRenameVariable::findsGlobals_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("configuration");
    QTest::addColumn<int>("resource");
    QTest::addColumn<QString>("type");
    QTest::newRow("configuration's, first") << QStringLiteral("alarm") << 0 << -1 << QStringLiteral("BOOL");
    QTest::newRow("resource's") << QStringLiteral("LEVEL") << 0 << 0 << QStringLiteral("INT");
    QTest::newRow("none") << QStringLiteral("Pressure") << -1 << -1 << QString();
}

void TestRenameVariable::findsGlobals()
{
    QFETCH(QString, name);
    QFETCH(int, configuration);
    QFETCH(int, resource);
    QFETCH(QString, type);
    const Instances instances = sampleInstances();
    QCOMPARE(findGlobal(instances, name), (GlobalLocation {configuration, resource}));
    const Variable *found = findGlobalVariable(instances, name);
    QCOMPARE(found ? std::get<ElementaryType>(found->type.kind).name : QString(), type);
}

void TestRenameVariable::globalRenameInInstances()
{
    const Instances before = sampleInstances();
    QVERIFY(!instancesWithGlobalRenamed(before, QStringLiteral("Pressure"), QStringLiteral("P")).has_value());

    Instances expected = before;
    expected.configurations[0].globalVars[0].variables[0].name = QStringLiteral("Fault");
    expected.configurations[0].resources[0].tasks[0].single = QStringLiteral("Fault");
    // The resource's Alarm is another variable (hidden by the configuration's): it stays.
    QCOMPARE(instancesWithGlobalRenamed(before, QStringLiteral("Alarm"), QStringLiteral("Fault")), expected);
}

void TestRenameVariable::globalRenameRedoUndoRedo()
{
    ProjectModel model;
    Project project;
    project.instances = sampleInstances();
    model.reset(project);
    const Project before = model.project();
    QUndoStack stack;
    stack.push(new SetInstancesCommand(
        model, *instancesWithGlobalRenamed(model.project().instances, QStringLiteral("Level"), QStringLiteral("Height"))));
    Project expected = before;
    expected.instances.configurations[0].resources[0].globalVars[0].variables[0].name = QStringLiteral("Height");
    expected.instances.configurations[0].resources[0].tasks[1].single = QStringLiteral("Height");
    QCOMPARE(model.project(), expected);
    stack.undo();
    QCOMPARE(model.project(), before);
    stack.redo();
    QCOMPARE(model.project(), expected);
}

QTEST_GUILESS_MAIN(TestRenameVariable)
#include "tst_renamevariable.moc"
