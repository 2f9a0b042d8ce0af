// Every undo command: redo, undo, redo against snapshots of the Project value, and merging of
// repeated edits of the same thing.

#include "model/undo/datatypecommands.h"
#include "model/undo/elementcommands.h"
#include "model/undo/instancecommands.h"
#include "model/undo/partcommands.h"
#include "model/undo/poucommands.h"
#include "model/undo/variablecommands.h"
#include "modelfixture.h"

#include <QTest>
#include <QUndoStack>

#include <functional>

using namespace iec::model;
using namespace iec::test;

namespace {

struct CommandCase {
    const char *name;
    std::function<QUndoCommand *(ProjectModel &)> make;
    std::function<bool(const ProjectModel &)> changedAsExpected; // checked after the first redo
};

// One configuration whose task and resource both run `program`.
Instances plantConfiguration(const char *program)
{
    PouInstance instance {.name = QStringLiteral("Plant"), .typeName = QLatin1String(program)};
    Task task {.name = QStringLiteral("Cyclic"), .interval = QStringLiteral("T#10ms"), .pouInstances = {instance}};
    Resource resource {.name = QStringLiteral("Cpu"), .tasks = {task}, .pouInstances = {instance}};
    return {.configurations = {{.name = QStringLiteral("Config"), .resources = {resource}}}};
}

BodyRef partOf(const ProjectModel &model, const char *pou, BodyRef::Part part, const char *name)
{
    return {pouId(model, pou), part, QLatin1String(name)};
}

const std::vector<CommandCase> &commandCases()
{
    static const std::vector<CommandCase> cases {
        {"add POU", [](ProjectModel &m) { return new AddPouCommand(m, {.name = QStringLiteral("New")}); },
            [](const ProjectModel &m) { return m.project().types.pous.back().name == QLatin1String("New"); }},
        {"remove POU", [](ProjectModel &m) { return new RemovePouCommand(m, pouId(m, "Motor")); },
            [](const ProjectModel &m) { return !m.project().findPou(QStringLiteral("Motor")); }},
        {"rename POU",
            [](ProjectModel &m) { return new RenamePouCommand(m, pouId(m, "Motor"), QStringLiteral("Drive")); },
            [](const ProjectModel &m) { return m.project().findPou(QStringLiteral("Drive")) != nullptr; }},
        {"duplicate POU",
            [](ProjectModel &m) { return new DuplicatePouCommand(m, pouId(m, "Chart"), QStringLiteral("Chart2")); },
            [](const ProjectModel &m) { return m.pouIndex(pouId(m, "Chart2")) == m.pouIndex(pouId(m, "Chart")) + 1; }},
        {"add action",
            [](ProjectModel &m) {
                return new AddPouPartCommand(m, pouId(m, "Chart"), BodyRef::Part::Action,
                    {.name = QStringLiteral("Blink"), .body = Body::withLanguage(BodyLanguage::ST)});
            },
            [](const ProjectModel &m) { return m.project().findPou(QStringLiteral("Chart"))->actions.size() == 1; }},
        {"remove action",
            [](ProjectModel &m) {
                return new RemovePouPartCommand(m, pouId(m, "Motor"), BodyRef::Part::Action, QStringLiteral("Reset"));
            },
            [](const ProjectModel &m) { return m.project().findPou(QStringLiteral("Motor"))->actions.empty(); }},
        {"rename action",
            [](ProjectModel &m) {
                return new RenamePouPartCommand(
                    m, pouId(m, "Motor"), BodyRef::Part::Action, QStringLiteral("Reset"), QStringLiteral("Clear"));
            },
            [](const ProjectModel &m) {
                return m.project().findPou(QStringLiteral("Motor"))->actions.front().name == QLatin1String("Clear");
            }},
        {"add transition",
            [](ProjectModel &m) {
                return new AddPouPartCommand(m, pouId(m, "Motor"), BodyRef::Part::Transition,
                    {.name = QStringLiteral("Ready"), .body = Body::withLanguage(BodyLanguage::FBD)});
            },
            [](const ProjectModel &m) {
                return m.project().findPou(QStringLiteral("Motor"))->transitions.size() == 2;
            }},
        {"remove transition",
            [](ProjectModel &m) {
                return new RemovePouPartCommand(
                    m, pouId(m, "Motor"), BodyRef::Part::Transition, QStringLiteral("Done"));
            },
            [](const ProjectModel &m) { return m.project().findPou(QStringLiteral("Motor"))->transitions.empty(); }},
        {"rename transition",
            [](ProjectModel &m) {
                return new RenamePouPartCommand(m, pouId(m, "Motor"), BodyRef::Part::Transition, QStringLiteral("Done"),
                    QStringLiteral("Finished"));
            },
            [](const ProjectModel &m) {
                return m.pouPartIndex(pouId(m, "Motor"), BodyRef::Part::Transition, QStringLiteral("Finished")) == 0;
            }},
        {"duplicate action",
            [](ProjectModel &m) {
                return AddPouPartCommand::duplicate(
                    m, pouId(m, "Motor"), BodyRef::Part::Action, QStringLiteral("Reset"), QStringLiteral("Reset2"));
            },
            [](const ProjectModel &m) {
                const Pou &motor = *m.project().findPou(QStringLiteral("Motor"));
                return motor.actions.size() == 2 && motor.actions[1].body == motor.actions[0].body
                    && !motor.actions[1].globalId;
            }},
        {"duplicate transition",
            [](ProjectModel &m) {
                return AddPouPartCommand::duplicate(
                    m, pouId(m, "Motor"), BodyRef::Part::Transition, QStringLiteral("Done"), QStringLiteral("Done2"));
            },
            [](const ProjectModel &m) {
                return m.pouPartIndex(pouId(m, "Motor"), BodyRef::Part::Transition, QStringLiteral("Done2")) == 1;
            }},
        {"duplicate data type",
            [](ProjectModel &m) {
                return AddDataTypeCommand::duplicate(m, QStringLiteral("Point"), QStringLiteral("Point3"));
            },
            [](const ProjectModel &m) {
                return m.project().findDataType(QStringLiteral("Point3"))->baseType
                    == m.project().findDataType(QStringLiteral("Point"))->baseType;
            }},
        {"duplicate variable",
            [](ProjectModel &m) {
                return AddVariableCommand::duplicate(
                    m, pouId(m, "Motor"), QStringLiteral("Pos"), QStringLiteral("Pos2"));
            },
            [](const ProjectModel &m) {
                const VarList &locals = m.project().findPou(QStringLiteral("Motor"))->pouInterface->varLists.at(4);
                return locals.variables.size() == 3
                    && locals.variables[2].initialValue == locals.variables[1].initialValue;
            }},
        {"rename variable",
            [](ProjectModel &m) {
                return ChangeVariableCommand::rename(
                    m, pouId(m, "Motor"), QStringLiteral("Count"), QStringLiteral("Total"));
            },
            [](const ProjectModel &m) {
                return m.findVariable(pouId(m, "Motor"), QStringLiteral("Total")) != nullptr;
            }},
        {"add data type", [](ProjectModel &m) { return new AddDataTypeCommand(m, {.name = QStringLiteral("Level")}); },
            [](const ProjectModel &m) { return m.dataTypeIndex(QStringLiteral("Level")) == 11; }},
        {"remove data type", [](ProjectModel &m) { return new RemoveDataTypeCommand(m, QStringLiteral("Matrix")); },
            [](const ProjectModel &m) { return m.dataTypeIndex(QStringLiteral("Matrix")) < 0; }},
        {"rename data type",
            [](ProjectModel &m) {
                return ChangeDataTypeCommand::rename(m, QStringLiteral("Colour"), QStringLiteral("Color"));
            },
            [](const ProjectModel &m) { return m.dataTypeIndex(QStringLiteral("Color")) == 5; }},
        {"change data type",
            [](ProjectModel &m) {
                DataTypeDecl type = *m.project().findDataType(QStringLiteral("Speed"));
                type.baseType.kind = ElementaryType {QStringLiteral("DINT")};
                return new ChangeDataTypeCommand(m, QStringLiteral("Speed"), type);
            },
            [](const ProjectModel &m) {
                return std::get<ElementaryType>(m.project().findDataType(QStringLiteral("Speed"))->baseType.kind).name
                    == QLatin1String("DINT");
            }},
        {"add variable in a new list",
            [](ProjectModel &m) {
                return new AddVariableCommand(m, pouId(m, "Chart"), VarListKind::Local, {.name = QStringLiteral("N")});
            },
            [](const ProjectModel &m) { return m.findVariable(pouId(m, "Chart"), QStringLiteral("N")) != nullptr; }},
        {"add variable to a list",
            [](ProjectModel &m) {
                return new AddVariableCommand(
                    m, pouId(m, "Motor"), VarListKind::Input, {.name = QStringLiteral("Stop")});
            },
            [](const ProjectModel &m) {
                return m.project().findPou(QStringLiteral("Motor"))->pouInterface->varLists.front().variables.size()
                    == 2;
            }},
        {"remove variable",
            [](ProjectModel &m) { return new RemoveVariableCommand(m, pouId(m, "Motor"), QStringLiteral("Timer")); },
            [](const ProjectModel &m) { return !m.findVariable(pouId(m, "Motor"), QStringLiteral("Timer")); }},
        {"change variable",
            [](ProjectModel &m) {
                Variable v = *m.findVariable(pouId(m, "Motor"), QStringLiteral("Start"));
                v.name = QStringLiteral("Run");
                v.initialValue = Value {SimpleValue {QStringLiteral("TRUE")}};
                return new ChangeVariableCommand(m, pouId(m, "Motor"), QStringLiteral("Start"), v);
            },
            [](const ProjectModel &m) { return m.findVariable(pouId(m, "Motor"), QStringLiteral("Run")) != nullptr; }},
        {"set interface", [](ProjectModel &m) { return new SetInterfaceCommand(m, pouId(m, "Motor"), Interface {}); },
            [](const ProjectModel &m) {
                return m.project().findPou(QStringLiteral("Motor"))->pouInterface->varLists.empty();
            }},
        {"insert element",
            [](ProjectModel &m) {
                Coil coil;
                coil.variable = QStringLiteral("Q9");
                return new InsertElementCommand(m, bodyOf(m, "Ladder"), coil, 2);
            },
            [](const ProjectModel &m) { return m.elementIndex(bodyOf(m, "Ladder"), 12) == 2; }},
        {"remove element with wires",
            [](ProjectModel &m) { return new RemoveElementCommand(m, bodyOf(m, "Blocks"), 2); },
            [](const ProjectModel &m) { return !m.element(bodyOf(m, "Blocks"), 2); }},
        {"move elements",
            [](ProjectModel &m) {
                return new MoveElementsCommand(m, bodyOf(m, "Ladder"), {{2, {1, 2}}, {3, {3, 4}}});
            },
            [](const ProjectModel &m) {
                return header(*m.element(bodyOf(m, "Ladder"), 3)).position == Position {3, 4};
            }},
        {"change element",
            [](ProjectModel &m) {
                auto contact = std::get<Contact>(*m.element(bodyOf(m, "Ladder"), 2));
                contact.negated = true;
                contact.variable = QStringLiteral("NotA");
                return new ChangeElementCommand(m, bodyOf(m, "Ladder"), contact);
            },
            [](const ProjectModel &m) { return std::get<Contact>(*m.element(bodyOf(m, "Ladder"), 2)).negated; }},
        {"connect", [](ProjectModel &m) { return new ConnectCommand(m, bodyOf(m, "Ladder"), 6, 0, {.refLocalId = 5}); },
            [](const ProjectModel &m) {
                return std::get<Coil>(*m.element(bodyOf(m, "Ladder"), 6)).connectionPointIn->connections.size() == 2;
            }},
        {"disconnect",
            [](ProjectModel &m) { return new DisconnectCommand(m, bodyOf(m, "Ladder"), 2, 0, 1, QString()); },
            [](const ProjectModel &m) {
                return std::get<Contact>(*m.element(bodyOf(m, "Ladder"), 2)).connectionPointIn->connections.empty();
            }},
        {"disconnect one of several wires",
            [](ProjectModel &m) { return new DisconnectCommand(m, bodyOf(m, "Chart"), 9, 0, 7); },
            [](const ProjectModel &m) {
                return std::get<SelectionConvergence>(*m.element(bodyOf(m, "Chart"), 9))
                    .connectionPointIns.front()
                    .connections.empty();
            }},
        {"set ST text",
            [](ProjectModel &m) {
                return new SetBodyTextCommand(m, bodyOf(m, "Scale"), QStringLiteral("Scale := 0;"));
            },
            [](const ProjectModel &m) { return m.body(bodyOf(m, "Scale"))->text() == QLatin1String("Scale := 0;"); }},
        {"set IL text of a transition",
            [](ProjectModel &m) {
                return new SetBodyTextCommand(
                    m, partOf(m, "Motor", BodyRef::Part::Transition, "Done"), QStringLiteral("LD TRUE"));
            },
            [](const ProjectModel &m) {
                return m.body(partOf(m, "Motor", BodyRef::Part::Transition, "Done"))->text()
                    == QLatin1String("LD TRUE");
            }},
        {"set configurations",
            [](ProjectModel &m) { return new SetInstancesCommand(m, plantConfiguration("Motor")); },
            [](const ProjectModel &m) { return m.project().instances == plantConfiguration("Motor"); }},
    };
    return cases;
}

} // namespace

class TestUndoCommands : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void redoUndoRedo_data();
    void redoUndoRedo();
    void repeatedEditsMerge_data();
    void repeatedEditsMerge();
    void editsOfDifferentThingsDoNotMerge();
    void commandsHaveTexts();
    void programRenameReachesTasksAndResources();
};

void TestUndoCommands::redoUndoRedo_data()
{
    QTest::addColumn<int>("index");
    for (std::size_t i = 0; i < commandCases().size(); ++i)
        QTest::newRow(commandCases()[i].name) << int(i);
}

void TestUndoCommands::redoUndoRedo()
{
    QFETCH(int, index);
    const CommandCase &command = commandCases()[std::size_t(index)];
    ProjectModel model;
    model.reset(everyElementProject());
    QUndoStack stack;
    const Project before = model.project();

    stack.push(command.make(model));
    const Project after = model.project();
    QVERIFY(!(after == before));
    QVERIFY(command.changedAsExpected(model));

    stack.undo();
    QVERIFY(model.project() == before);
    stack.redo();
    QVERIFY(model.project() == after);
    stack.undo();
    QVERIFY(model.project() == before);
}

void TestUndoCommands::repeatedEditsMerge_data()
{
    QTest::addColumn<int>("first");
    QTest::addColumn<int>("second");
    // Pairs of (command case, follow-up that continues the same edit) by name below.
    QTest::addColumn<QString>("kind");
    QTest::newRow("move") << 0 << 0 << QStringLiteral("move");
    QTest::newRow("text") << 0 << 0 << QStringLiteral("text");
    QTest::newRow("variable") << 0 << 0 << QStringLiteral("variable");
    QTest::newRow("element") << 0 << 0 << QStringLiteral("element");
    QTest::newRow("action rename") << 0 << 0 << QStringLiteral("actionRename");
    QTest::newRow("type rename") << 0 << 0 << QStringLiteral("typeRename");
}

void TestUndoCommands::repeatedEditsMerge()
{
    QFETCH(QString, kind);
    ProjectModel model;
    model.reset(everyElementProject());
    QUndoStack stack;
    const Project before = model.project();
    const BodyRef ladder = bodyOf(model, "Ladder");
    const PouId motor = pouId(model, "Motor");

    for (int step = 1; step <= 3; ++step) {
        const QString text = QStringLiteral("step%1").arg(step);
        if (kind == QLatin1String("move")) {
            stack.push(new MoveElementsCommand(model, ladder, {{2, {double(step), 0}}}));
        } else if (kind == QLatin1String("text")) {
            stack.push(new SetBodyTextCommand(model, bodyOf(model, "Scale"), text));
        } else if (kind == QLatin1String("variable")) { // renames chain: Start -> step1 -> step2 -> step3
            const QString name = step == 1 ? QStringLiteral("Start") : QStringLiteral("step%1").arg(step - 1);
            Variable v = *model.findVariable(motor, name);
            v.name = text;
            stack.push(new ChangeVariableCommand(model, motor, name, v));
        } else if (kind == QLatin1String("element")) {
            auto contact = std::get<Contact>(*model.element(ladder, 2));
            contact.variable = text;
            stack.push(new ChangeElementCommand(model, ladder, contact));
        } else if (kind == QLatin1String("actionRename")) {
            const QString name = step == 1 ? QStringLiteral("Reset") : QStringLiteral("step%1").arg(step - 1);
            stack.push(new RenamePouPartCommand(model, motor, BodyRef::Part::Action, name, text));
        } else if (kind == QLatin1String("typeRename")) { // Colour -> step1 -> step2 -> step3
            const QString name = step == 1 ? QStringLiteral("Colour") : QStringLiteral("step%1").arg(step - 1);
            stack.push(ChangeDataTypeCommand::rename(model, name, text));
        }
    }
    QCOMPARE(stack.count(), 1);
    const Project after = model.project();
    stack.undo();
    QVERIFY(model.project() == before);
    stack.redo();
    QVERIFY(model.project() == after);
}

void TestUndoCommands::editsOfDifferentThingsDoNotMerge()
{
    ProjectModel model;
    model.reset(everyElementProject());
    QUndoStack stack;
    const BodyRef ladder = bodyOf(model, "Ladder");
    stack.push(new MoveElementsCommand(model, ladder, {{2, {1, 1}}}));
    stack.push(new MoveElementsCommand(model, ladder, {{3, {1, 1}}}));
    stack.push(new SetBodyTextCommand(model, bodyOf(model, "Scale"), QStringLiteral("a")));
    stack.push(new SetBodyTextCommand(model, {pouId(model, "Motor"), BodyRef::Part::Pou, {}}, QStringLiteral("b")));
    stack.push(new RenamePouCommand(model, pouId(model, "Motor"), QStringLiteral("M")));
    stack.push(new RenamePouCommand(model, pouId(model, "Chart"), QStringLiteral("C")));
    QCOMPARE(stack.count(), 6);
    // Declarations applied are one gesture each, even of the same thing.
    for (const char *name : {"a", "b"}) {
        Interface declarations;
        declarations.varLists.push_back({.kind = VarListKind::Local});
        declarations.varLists.back().variables.push_back({.name = QString::fromLatin1(name)});
        stack.push(new SetInterfaceCommand(model, pouId(model, "M"), declarations));
    }
    QCOMPARE(stack.count(), 8);
    // Edits of different fields of one variable or one type are steps of their own.
    const PouId m = pouId(model, "M");
    Variable b = *model.findVariable(m, QStringLiteral("b"));
    b.name = QStringLiteral("c");
    stack.push(new ChangeVariableCommand(model, m, QStringLiteral("b"), b));
    b.type = {ElementaryType {QStringLiteral("INT")}};
    stack.push(new ChangeVariableCommand(model, m, QStringLiteral("c"), b));
    QCOMPARE(stack.count(), 10);
    stack.push(ChangeDataTypeCommand::rename(model, QStringLiteral("Colour"), QStringLiteral("Hue")));
    DataTypeDecl hue = *model.project().findDataType(QStringLiteral("Hue"));
    hue.initialValue = Value {SimpleValue {QStringLiteral("Red")}};
    stack.push(new ChangeDataTypeCommand(model, QStringLiteral("Hue"), hue));
    QCOMPARE(stack.count(), 12);
}

void TestUndoCommands::commandsHaveTexts()
{
    ProjectModel model;
    model.reset(everyElementProject());
    for (const CommandCase &command : commandCases()) {
        std::unique_ptr<QUndoCommand> made(command.make(model));
        QVERIFY2(!made->text().isEmpty(), command.name);
    }
    std::unique_ptr<QUndoCommand> move(new MoveElementsCommand(model, bodyOf(model, "Ladder"), {{2, {}}, {3, {}}}));
    QCOMPARE(move->text(), QStringLiteral("Move 2 element(s)"));
}

QTEST_GUILESS_MAIN(TestUndoCommands)
void TestUndoCommands::programRenameReachesTasksAndResources()
{
    const std::optional<Instances> renamed
        = instancesWithProgramRenamed(plantConfiguration("Motor"), QStringLiteral("MOTOR"), QStringLiteral("Drive"));
    QVERIFY(renamed.has_value());
    QCOMPARE(*renamed, plantConfiguration("Drive"));
    QVERIFY(!instancesWithProgramRenamed(plantConfiguration("Motor"), QStringLiteral("Pump"), QStringLiteral("X")));
}

#include "tst_undocommands.moc"
