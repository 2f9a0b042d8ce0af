// Renames of variables, globals and struct members reach every use in one undo step
// (app/referencerename), the declaration editor's rename gesture, and File → Import merging
// configurations (app/importexport). Every case checks the exact model after redo, undo, redo.
#include "app/documentarea.h"
#include "app/importexport.h"
#include "app/namerules.h"
#include "app/projectcommands.h"
#include "app/referencerename.h"
#include "app/undostacks.h"
#include "editors/text/codeeditor.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/declarations/declarationtablemodel.h"
#include "model/projectmodel.h"

#include <QTest>
#include <QTextCursor>
#include <QUndoStack>

#include <functional>

using namespace iec::app;
using namespace iec::model;

class TestVariableRename : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void renameIdentifiersInText_data();
    void renameIdentifiersInText();
    void renameReachesEveryUse_data();
    void renameReachesEveryUse();
    void memberRenameFollowsDeclaredTypes_data();
    void memberRenameFollowsDeclaredTypes();
    void functionInputRenameReachesCalls();
    void declarationEditorRenameIsOneStep();
    void declarationEditorWithoutRenameChangesDeclarationsOnly();
    void documentAreaRenameTakesPendingTypingAlong();
    void freeNamesOnImport_data();
    void freeNamesOnImport();
    void importMergesConfigurations();
    void importIntoOtherConfigurationOrNone();
};

namespace {

// ---- building the sample project

Variable variable(const QString &name, const QString &type = QStringLiteral("BOOL"))
{
    Variable v;
    v.name = name;
    v.type.kind = ElementaryType {.name = type};
    return v;
}

Variable instanceOf(const QString &name, const QString &type)
{
    Variable v;
    v.name = name;
    v.type.kind = DerivedType {.name = type};
    return v;
}

Variable arrayOf(const QString &name, const QString &type)
{
    Variable v;
    v.name = name;
    v.type.kind = ArrayType {.dimensions = {{QStringLiteral("1"), QStringLiteral("3")}},
        .baseType = DataType {DerivedType {.name = type}}};
    return v;
}

Pou pouOf(const QString &name, PouKind kind, BodyLanguage language, std::vector<VarList> lists)
{
    Pou pou = makePou({.name = name, .kind = kind, .language = iec::editors::editorLanguage(Body::withLanguage(language))});
    pou.pouInterface->varLists = std::move(lists);
    return pou;
}

Pou stPou(const QString &name, PouKind kind, const QString &text, std::vector<VarList> lists = {})
{
    Pou pou = pouOf(name, kind, BodyLanguage::ST, std::move(lists));
    pou.bodies.front().setText(text);
    return pou;
}

PouPart part(const QString &name, BodyLanguage language, const QString &text)
{
    PouPart value {.name = name, .body = Body::withLanguage(language)};
    value.body.setText(text);
    return value;
}

const QString kMainText = QStringLiteral("(* Count counts *)\n"
                                         "Count := Count + 1; // Count\n"
                                         "msg := 'Count';\n"
                                         "M1(Start := Flag, Running => Flag);\n"
                                         "Pos.X := COUNT;\n"
                                         "Path[Count].X := Pos.Y + M1.Running;\n"
                                         "IF Alarm THEN Count := 0; END_IF");
const QString kIncText = QStringLiteral("LD Count\nADD 1\nST Count\nCAL M1(Start := Flag)\nLD M1.Running\nST Flag");

Pou ladder()
{
    Pou pou = pouOf(QStringLiteral("Ladder"), PouKind::Program, BodyLanguage::LD,
        {VarList {.variables = {variable(QStringLiteral("Flag")), instanceOf(QStringLiteral("M"), QStringLiteral("Motor"))}}});
    std::vector<Element> &elements = *pou.bodies.front().elements();
    Contact contact;
    contact.localId = 2;
    contact.variable = QStringLiteral("Flag");
    Coil coil;
    coil.localId = 3;
    coil.variable = QStringLiteral("flag");
    Block block;
    block.localId = 4;
    block.typeName = QStringLiteral("Motor");
    block.instanceName = QStringLiteral("M");
    block.inputVariables = {BlockVariable {.formalParameter = QStringLiteral("Start")}};
    block.outputVariables = {BlockVariable {.formalParameter = QStringLiteral("Running")}};
    InVariable in;
    in.localId = 5;
    in.expression = QStringLiteral("Flag");
    OutVariable out;
    out.localId = 6;
    out.expression = QStringLiteral("Flag");
    out.connectionPointIn = ConnectionPointIn {
        .connections = {Connection {.refLocalId = 4, .formalParameter = QStringLiteral("Running")}}};
    elements = {contact, coil, block, in, out};
    return pou;
}

Pou chart()
{
    Pou pou = pouOf(QStringLiteral("Seq"), PouKind::Program, BodyLanguage::SFC,
        {VarList {.variables = {variable(QStringLiteral("Go")), variable(QStringLiteral("Lamp"))}}});
    pou.actions.push_back(part(QStringLiteral("Fill"), BodyLanguage::ST, QStringLiteral("Lamp := TRUE;")));
    std::vector<Element> &elements = *pou.bodies.front().elements();
    Step step;
    step.localId = 1;
    step.name = QStringLiteral("Init");
    Body condition = Body::withLanguage(BodyLanguage::ST);
    condition.setText(QStringLiteral("Go AND NOT Lamp"));
    Transition inlined;
    inlined.localId = 2;
    inlined.condition = Condition {.kind = InlineCondition {.body = condition}};
    ActionBlock actions;
    actions.localId = 3;
    ActionBlockAction light;
    light.qualifier = QStringLiteral("N");
    light.reference = Reference {QStringLiteral("Lamp")};
    light.indicator = QStringLiteral("Go");
    ActionBlockAction fill;
    fill.reference = Reference {QStringLiteral("Fill")};
    actions.actions = {light, fill};
    Transition named;
    named.localId = 4;
    named.condition = Condition {.kind = Reference {QStringLiteral("T1")}};
    elements = {step, inlined, actions, named};
    return pou;
}

// Point: a struct. Motor: a function block. Main (ST, with an IL action and an ST transition)
// uses a Point, an array of them, a Motor and the global Alarm (VAR_EXTERNAL). Ladder (LD) and
// Seq (SFC) use their own variables. Other hides the global with a local Alarm; Uses reads the
// global without declaring it (CODESYS style). Config/Res declare Alarm; task Fast starts on it.
Project sampleProject()
{
    Project project;
    DataTypeDecl point;
    point.name = QStringLiteral("Point");
    point.baseType.kind = StructType {.members = {variable(QStringLiteral("X"), QStringLiteral("INT")),
                                          variable(QStringLiteral("Y"), QStringLiteral("INT"))}};
    project.types.dataTypes.push_back(point);
    project.types.pous.push_back(stPou(QStringLiteral("Motor"), PouKind::FunctionBlock,
        QStringLiteral("Running := Start AND NOT Running;"),
        {VarList {.kind = VarListKind::Input, .variables = {variable(QStringLiteral("Start"))}},
            VarList {.kind = VarListKind::Output, .variables = {variable(QStringLiteral("Running"))}}}));
    Variable pos = instanceOf(QStringLiteral("Pos"), QStringLiteral("Point"));
    pos.initialValue = Value {StructValue {{{QStringLiteral("X"), Value {SimpleValue {QStringLiteral("1")}}},
        {QStringLiteral("Y"), Value {SimpleValue {QStringLiteral("2")}}}}}};
    Pou main = stPou(QStringLiteral("Main"), PouKind::Program, kMainText,
        {VarList {.variables = {variable(QStringLiteral("Count"), QStringLiteral("INT")), pos,
                      instanceOf(QStringLiteral("M1"), QStringLiteral("Motor")),
                      arrayOf(QStringLiteral("Path"), QStringLiteral("Point")), variable(QStringLiteral("Flag"))}},
            VarList {.kind = VarListKind::External, .variables = {variable(QStringLiteral("Alarm"))}}});
    main.actions.push_back(part(QStringLiteral("Inc"), BodyLanguage::IL, kIncText));
    main.transitions.push_back(part(QStringLiteral("T1"), BodyLanguage::ST, QStringLiteral("Count > 5 AND Pos.X > 0")));
    project.types.pous.push_back(main);
    project.types.pous.push_back(ladder());
    project.types.pous.push_back(chart());
    project.types.pous.push_back(stPou(QStringLiteral("Other"), PouKind::Program, QStringLiteral("Alarm := TRUE;"),
        {VarList {.variables = {variable(QStringLiteral("Alarm"))}}}));
    project.types.pous.push_back(stPou(QStringLiteral("Uses"), PouKind::Program, QStringLiteral("x := Alarm;")));

    Task fast;
    fast.name = QStringLiteral("Fast");
    fast.single = QStringLiteral("Alarm");
    fast.pouInstances.push_back(PouInstance {.name = QStringLiteral("MainInst"), .typeName = QStringLiteral("Main")});
    Resource resource;
    resource.name = QStringLiteral("Res");
    resource.tasks.push_back(fast);
    resource.globalVars.push_back(VarList {.kind = VarListKind::Global, .variables = {variable(QStringLiteral("Alarm"))}});
    Configuration configuration;
    configuration.name = QStringLiteral("Config");
    configuration.resources.push_back(resource);
    project.instances.configurations.push_back(configuration);
    return project;
}

// ---- reaching into a project value (the expected states are written as edits of the sample)

Pou &pouNamed(Project &project, const QString &name)
{
    return *std::ranges::find_if(project.types.pous, [&](const Pou &p) { return p.name == name; });
}

Variable &declared(Pou &pou, const QString &name)
{
    for (VarList &list : pou.pouInterface->varLists) {
        for (Variable &v : list.variables) {
            if (v.name == name)
                return v;
        }
    }
    qFatal("no variable %s", qPrintable(name));
}

template<class T> T &elementOf(Pou &pou, quint64 localId)
{
    for (Element &element : *pou.bodies.front().elements()) {
        if (header(element).localId == localId)
            return std::get<T>(element);
    }
    qFatal("no element %llu", localId);
}

void replaceIn(Body &body, const QString &from, const QString &to)
{
    QString text = body.text();
    QVERIFY2(text.contains(from), qPrintable(from));
    body.setText(text.replace(from, to));
}

void setMainText(Project &project, const QString &text)
{
    pouNamed(project, QStringLiteral("Main")).bodies.front().setText(text);
}

// Which part of two projects differs first, for a readable failure.
QString firstDifference(const Project &actual, const Project &expected)
{
    if (actual.types.dataTypes != expected.types.dataTypes)
        return QStringLiteral("data types");
    if (actual.instances != expected.instances)
        return QStringLiteral("configurations");
    if (actual.types.pous.size() != expected.types.pous.size())
        return QStringLiteral("number of POUs");
    for (size_t i = 0; i < actual.types.pous.size(); ++i) {
        const Pou &a = actual.types.pous[i];
        const Pou &e = expected.types.pous[i];
        if (a.pouInterface != e.pouInterface)
            return a.name + QStringLiteral(": declarations");
        if (a.bodies != e.bodies) {
            return a.name + QStringLiteral(": body\n") + (a.body()->isGraphical() ? QString() : a.body()->text())
                + QStringLiteral("\nexpected\n") + (e.body()->isGraphical() ? QString() : e.body()->text());
        }
        if (a.actions != e.actions || a.transitions != e.transitions)
            return a.name + QStringLiteral(": actions or transitions");
        if (a != e)
            return a.name;
    }
    return actual == expected ? QString() : QStringLiteral("elsewhere");
}

#define COMPARE_PROJECT(actual, expected)                                                                              \
    QVERIFY2((actual) == (expected), qPrintable(firstDifference((actual), (expected))))

using Operation = std::function<QUndoCommand *(ProjectModel &)>;
using Expectation = std::function<void(Project &)>;

struct RenameCase {
    const char *name;
    Operation operation;
    Expectation expected;
};

PouId idOf(const ProjectModel &model, const char *name)
{
    return model.project().findPou(QLatin1String(name))->id;
}

Operation renameVariable(const char *pou, const char *oldName, const char *newName)
{
    return [=](ProjectModel &model) {
        return createRenameVariableCommand(model, idOf(model, pou), QLatin1String(oldName), QLatin1String(newName));
    };
}

// The rename of Main's Count as one expectation (the editor gesture test checks it too).
void countRenamedToCounter(Project &p)
{
    Pou &main = pouNamed(p, QStringLiteral("Main"));
    declared(main, QStringLiteral("Count")).name = QStringLiteral("Counter");
    setMainText(p,
        QStringLiteral("(* Count counts *)\n"
                       "Counter := Counter + 1; // Count\n"
                       "msg := 'Count';\n"
                       "M1(Start := Flag, Running => Flag);\n"
                       "Pos.X := Counter;\n"
                       "Path[Counter].X := Pos.Y + M1.Running;\n"
                       "IF Alarm THEN Counter := 0; END_IF"));
    main.actions[0].body.setText(
        QStringLiteral("LD Counter\nADD 1\nST Counter\nCAL M1(Start := Flag)\nLD M1.Running\nST Flag"));
    main.transitions[0].body.setText(QStringLiteral("Counter > 5 AND Pos.X > 0"));
}

const std::vector<RenameCase> &renameCases()
{
    static const std::vector<RenameCase> cases {
        {"local variable: ST body, IL action, ST transition", renameVariable("Main", "Count", "Counter"),
            countRenamedToCounter},
        {"function block input: its body, calls, IL calls, LD pins", renameVariable("Motor", "Start", "Enable"),
            [](Project &p) {
                Pou &motor = pouNamed(p, QStringLiteral("Motor"));
                declared(motor, QStringLiteral("Start")).name = QStringLiteral("Enable");
                motor.bodies.front().setText(QStringLiteral("Running := Enable AND NOT Running;"));
                Pou &main = pouNamed(p, QStringLiteral("Main"));
                replaceIn(main.bodies.front(), QStringLiteral("M1(Start :="), QStringLiteral("M1(Enable :="));
                replaceIn(main.actions[0].body, QStringLiteral("M1(Start :="), QStringLiteral("M1(Enable :="));
                elementOf<Block>(pouNamed(p, QStringLiteral("Ladder")), 4).inputVariables[0].formalParameter
                    = QStringLiteral("Enable");
            }},
        {"function block output: members, outputs of calls, pins and wires", renameVariable("Motor", "Running", "Busy"),
            [](Project &p) {
                Pou &motor = pouNamed(p, QStringLiteral("Motor"));
                declared(motor, QStringLiteral("Running")).name = QStringLiteral("Busy");
                motor.bodies.front().setText(QStringLiteral("Busy := Start AND NOT Busy;"));
                Pou &main = pouNamed(p, QStringLiteral("Main"));
                replaceIn(main.bodies.front(), QStringLiteral("Running => Flag"), QStringLiteral("Busy => Flag"));
                replaceIn(main.bodies.front(), QStringLiteral("M1.Running"), QStringLiteral("M1.Busy"));
                replaceIn(main.actions[0].body, QStringLiteral("M1.Running"), QStringLiteral("M1.Busy"));
                Pou &ladder = pouNamed(p, QStringLiteral("Ladder"));
                elementOf<Block>(ladder, 4).outputVariables[0].formalParameter = QStringLiteral("Busy");
                elementOf<OutVariable>(ladder, 6).connectionPointIn->connections[0].formalParameter
                    = QStringLiteral("Busy");
            }},
        {"LD contacts, coils and variables (any case)", renameVariable("Ladder", "Flag", "Ready"),
            [](Project &p) {
                Pou &ladder = pouNamed(p, QStringLiteral("Ladder"));
                declared(ladder, QStringLiteral("Flag")).name = QStringLiteral("Ready");
                elementOf<Contact>(ladder, 2).variable = QStringLiteral("Ready");
                elementOf<Coil>(ladder, 3).variable = QStringLiteral("Ready");
                elementOf<InVariable>(ladder, 5).expression = QStringLiteral("Ready");
                elementOf<OutVariable>(ladder, 6).expression = QStringLiteral("Ready");
            }},
        {"block instance", renameVariable("Ladder", "M", "Motor1"),
            [](Project &p) {
                Pou &ladder = pouNamed(p, QStringLiteral("Ladder"));
                declared(ladder, QStringLiteral("M")).name = QStringLiteral("Motor1");
                elementOf<Block>(ladder, 4).instanceName = QStringLiteral("Motor1");
            }},
        {"SFC: inline condition, action block naming a variable, action body", renameVariable("Seq", "Lamp", "Light"),
            [](Project &p) {
                Pou &seq = pouNamed(p, QStringLiteral("Seq"));
                declared(seq, QStringLiteral("Lamp")).name = QStringLiteral("Light");
                std::get<InlineCondition>(elementOf<Transition>(seq, 2).condition->kind).body->setText(
                    QStringLiteral("Go AND NOT Light"));
                elementOf<ActionBlock>(seq, 3).actions[0].reference = Reference {QStringLiteral("Light")};
                seq.actions[0].body.setText(QStringLiteral("Light := TRUE;"));
            }},
        {"SFC: qualifier indicator", renameVariable("Seq", "Go", "Run"),
            [](Project &p) {
                Pou &seq = pouNamed(p, QStringLiteral("Seq"));
                declared(seq, QStringLiteral("Go")).name = QStringLiteral("Run");
                std::get<InlineCondition>(elementOf<Transition>(seq, 2).condition->kind).body->setText(
                    QStringLiteral("Run AND NOT Lamp"));
                elementOf<ActionBlock>(seq, 3).actions[0].indicator = QStringLiteral("Run");
            }},
        {"global: configuration, task, VAR_EXTERNAL, implicit use; a local of that name stays",
            [](ProjectModel &model) {
                return createRenameGlobalVariableCommand(model, QStringLiteral("Alarm"), QStringLiteral("Fault"));
            },
            [](Project &p) {
                Resource &resource = p.instances.configurations[0].resources[0];
                resource.globalVars[0].variables[0].name = QStringLiteral("Fault");
                resource.tasks[0].single = QStringLiteral("Fault");
                Pou &main = pouNamed(p, QStringLiteral("Main"));
                declared(main, QStringLiteral("Alarm")).name = QStringLiteral("Fault");
                replaceIn(main.bodies.front(), QStringLiteral("IF Alarm"), QStringLiteral("IF Fault"));
                pouNamed(p, QStringLiteral("Uses")).bodies.front().setText(QStringLiteral("x := Fault;"));
            }},
        {"struct member: x.M and a[i].M where the type is known",
            [](ProjectModel &model) {
                return createRenameMemberCommand(model, QStringLiteral("Point"), QStringLiteral("X"), QStringLiteral("PosX"));
            },
            [](Project &p) {
                std::get<StructType>(p.types.dataTypes[0].baseType.kind).members[0].name = QStringLiteral("PosX");
                Pou &main = pouNamed(p, QStringLiteral("Main"));
                std::get<StructValue>(declared(main, QStringLiteral("Pos")).initialValue->kind).values[0].member
                    = QStringLiteral("PosX");
                replaceIn(main.bodies.front(), QStringLiteral("Pos.X :="), QStringLiteral("Pos.PosX :="));
                replaceIn(main.bodies.front(), QStringLiteral("Path[Count].X"), QStringLiteral("Path[Count].PosX"));
                main.transitions[0].body.setText(QStringLiteral("Count > 5 AND Pos.PosX > 0"));
            }},
        {"unknown variable: nothing", renameVariable("Main", "Nothing", "Something"), [](Project &) {}},
    };
    return cases;
}

} // namespace

void TestVariableRename::renameIdentifiersInText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("il");
    QTest::addColumn<QString>("expected");
    QTest::newRow("assignment") << QStringLiteral("Count := Count + 1;") << false << QStringLiteral("N := N + 1;");
    QTest::newRow("case-insensitive") << QStringLiteral("COUNT := count;") << false << QStringLiteral("N := N;");
    QTest::newRow("comments and strings stay") << QStringLiteral("(* Count *) s := 'Count'; // Count\nw := \"Count\";")
                                               << false
                                               << QStringLiteral("(* Count *) s := 'Count'; // Count\nw := \"Count\";");
    QTest::newRow("nested comment stays") << QStringLiteral("(* a (* Count *) Count *) Count") << false
                                          << QStringLiteral("(* a (* Count *) Count *) N");
    QTest::newRow("pragma stays") << QStringLiteral("{Count} Count") << false << QStringLiteral("{Count} N");
    QTest::newRow("member of another instance stays") << QStringLiteral("x := fb.Count + Count.Q;") << false
                                                      << QStringLiteral("x := fb.Count + N.Q;");
    QTest::newRow("formal parameter stays, argument renamed") << QStringLiteral("fb(Count := Count, Q => Count);")
                                                              << false << QStringLiteral("fb(Count := N, Q => N);");
    QTest::newRow("longer names stay") << QStringLiteral("Count_2 := MyCount;") << false
                                       << QStringLiteral("Count_2 := MyCount;");
    QTest::newRow("index and CASE label") << QStringLiteral("CASE a[Count] OF Count: x := 1; END_CASE") << false
                                          << QStringLiteral("CASE a[N] OF N: x := 1; END_CASE");
    QTest::newRow("IL operands") << QStringLiteral("LD Count\nADD 1\nST Count") << true
                                 << QStringLiteral("LD N\nADD 1\nST N");
    QTest::newRow("IL labels stay") << QStringLiteral("JMPC Count\nLD Count\nCount: ST x") << true
                                    << QStringLiteral("JMPC Count\nLD N\nCount: ST x");
}

void TestVariableRename::renameIdentifiersInText()
{
    QFETCH(QString, text);
    QFETCH(bool, il);
    QFETCH(QString, expected);
    QCOMPARE(renameIdentifiers(text, {{QStringLiteral("Count"), QStringLiteral("N")}},
                 il ? TextDialect::IL : TextDialect::ST),
        expected);
    // Two names swapped at once.
    QCOMPARE(renameIdentifiers(QStringLiteral("a := b; b := a;"),
                 {{QStringLiteral("a"), QStringLiteral("b")}, {QStringLiteral("b"), QStringLiteral("a")}}),
        QStringLiteral("b := a; a := b;"));
}

void TestVariableRename::renameReachesEveryUse_data()
{
    QTest::addColumn<int>("index");
    for (size_t i = 0; i < renameCases().size(); ++i)
        QTest::newRow(renameCases()[i].name) << int(i);
}

void TestVariableRename::renameReachesEveryUse()
{
    QFETCH(int, index);
    const RenameCase &rename = renameCases()[size_t(index)];
    ProjectModel model;
    model.reset(sampleProject());
    const Project before = model.project();
    Project expected = before;
    rename.expected(expected);

    QUndoStack stack;
    stack.push(rename.operation(model));
    QCOMPARE(stack.count(), 1);
    COMPARE_PROJECT(model.project(), expected);
    stack.undo();
    COMPARE_PROJECT(model.project(), before);
    stack.redo();
    COMPARE_PROJECT(model.project(), expected);
}

void TestVariableRename::memberRenameFollowsDeclaredTypes_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    QTest::newRow("member of a variable; a variable of that name stays") << QStringLiteral("p.X := X;")
                                                                         << QStringLiteral("p.PosX := X;");
    QTest::newRow("nested struct") << QStringLiteral("line.Inner.X := 1;") << QStringLiteral("line.Inner.PosX := 1;");
    QTest::newRow("array elements, index inside index") << QStringLiteral("a[a[1].X].X := 0;")
                                                        << QStringLiteral("a[a[1].PosX].PosX := 0;");
    QTest::newRow("alias of the type") << QStringLiteral("alias.x := 2;") << QStringLiteral("alias.PosX := 2;");
    QTest::newRow("another struct's member of that name stays") << QStringLiteral("q.X := p.Y;")
                                                                << QStringLiteral("q.X := p.Y;");
    QTest::newRow("comments and strings stay") << QStringLiteral("(* p.X *) s := 'p.X';")
                                               << QStringLiteral("(* p.X *) s := 'p.X';");
}

void TestVariableRename::memberRenameFollowsDeclaredTypes()
{
    QFETCH(QString, text);
    QFETCH(QString, expected);
    Project project = sampleProject();
    DataTypeDecl line;
    line.name = QStringLiteral("Line");
    line.baseType.kind = StructType {.members = {instanceOf(QStringLiteral("Inner"), QStringLiteral("Point"))}};
    DataTypeDecl alias;
    alias.name = QStringLiteral("PointAlias");
    alias.baseType.kind = DerivedType {.name = QStringLiteral("Point")};
    DataTypeDecl other;
    other.name = QStringLiteral("Other3");
    other.baseType.kind = StructType {.members = {variable(QStringLiteral("X"), QStringLiteral("INT"))}};
    project.types.dataTypes.insert(project.types.dataTypes.end(), {line, alias, other});
    project.types.pous.push_back(stPou(QStringLiteral("Calc"), PouKind::Program, text,
        {VarList {.variables = {instanceOf(QStringLiteral("p"), QStringLiteral("Point")),
                      instanceOf(QStringLiteral("line"), QStringLiteral("Line")), arrayOf(QStringLiteral("a"), QStringLiteral("Point")),
                      instanceOf(QStringLiteral("alias"), QStringLiteral("PointAlias")),
                      instanceOf(QStringLiteral("q"), QStringLiteral("Other3")), variable(QStringLiteral("X"), QStringLiteral("INT"))}}}));
    ProjectModel model;
    model.reset(project);
    std::unique_ptr<QUndoCommand> rename(
        createRenameMemberCommand(model, QStringLiteral("Point"), QStringLiteral("X"), QStringLiteral("PosX")));
    rename->redo();
    QCOMPARE(model.project().findPou(QStringLiteral("Calc"))->body()->text(), expected);
    rename->undo();
    QCOMPARE(model.project().findPou(QStringLiteral("Calc"))->body()->text(), text);
}

void TestVariableRename::functionInputRenameReachesCalls()
{
    // A function's input is named in calls: Scale(In := 2). The caller's own In stays.
    Project project;
    Pou scale = stPou(QStringLiteral("Scale"), PouKind::Function, QStringLiteral("Scale := In * 2;"),
        {VarList {.kind = VarListKind::Input, .variables = {variable(QStringLiteral("In"), QStringLiteral("INT"))}}});
    project.types.pous.push_back(scale);
    project.types.pous.push_back(stPou(QStringLiteral("Caller"), PouKind::Program,
        QStringLiteral("y := Scale(In := In) + Scale(In);"),
        {VarList {.variables = {variable(QStringLiteral("In"), QStringLiteral("INT"))}}}));
    ProjectModel model;
    model.reset(project);
    const Project before = model.project();
    QUndoStack stack;
    stack.push(createRenameVariableCommand(model, idOf(model, "Scale"), QStringLiteral("In"), QStringLiteral("Value")));
    QCOMPARE(model.project().findPou(QStringLiteral("Scale"))->body()->text(), QStringLiteral("Scale := Value * 2;"));
    QCOMPARE(model.project().findPou(QStringLiteral("Caller"))->body()->text(),
        QStringLiteral("y := Scale(Value := In) + Scale(In);"));
    stack.undo();
    COMPARE_PROJECT(model.project(), before);
}

void TestVariableRename::declarationEditorRenameIsOneStep()
{
    ProjectModel model;
    model.reset(sampleProject());
    const Project before = model.project();
    Project expected = before;
    countRenamedToCounter(expected);
    QUndoStack stack;
    iec::editors::DeclarationEditor editor(model, idOf(model, "Main"), stack);
    editor.setRenameReferences([&model](PouId pou, const Renames &renames, QUndoCommand *gesture) {
        addVariableReferenceRenames(model, pou, renames, gesture);
    });
    // The user types the new name into the Name cell of Count (the first row).
    iec::editors::DeclarationTableModel *table = editor.tableModel();
    QCOMPARE(table->rows().front().name, QStringLiteral("Count"));
    QVERIFY(table->setData(table->index(0, int(iec::editors::DeclarationColumn::Name)), QStringLiteral("Counter")));

    QCOMPARE(stack.count(), 1);
    QCOMPARE(stack.undoText(), QStringLiteral("Rename variable Count to Counter"));
    COMPARE_PROJECT(model.project(), expected);
    stack.undo();
    COMPARE_PROJECT(model.project(), before);
    QCOMPARE(editor.tableModel()->rows().front().name, QStringLiteral("Count"));
    stack.redo();
    COMPARE_PROJECT(model.project(), expected);
}

void TestVariableRename::declarationEditorWithoutRenameChangesDeclarationsOnly()
{
    // A type change is no rename: the bodies stay, whatever the hook would do.
    ProjectModel model;
    model.reset(sampleProject());
    const Project before = model.project();
    QUndoStack stack;
    iec::editors::DeclarationEditor editor(model, idOf(model, "Main"), stack);
    int hookCalls = 0;
    editor.setRenameReferences([&](PouId, const Renames &, QUndoCommand *) { ++hookCalls; });
    iec::editors::DeclarationTableModel *table = editor.tableModel();
    QVERIFY(table->setData(table->index(0, int(iec::editors::DeclarationColumn::Type)), QStringLiteral("DINT")));
    QCOMPARE(stack.count(), 1);
    QCOMPARE(hookCalls, 0);
    Project expected = before;
    declared(pouNamed(expected, QStringLiteral("Main")), QStringLiteral("Count")).type.kind
        = ElementaryType {.name = QStringLiteral("DINT")};
    COMPARE_PROJECT(model.project(), expected);
}

void TestVariableRename::documentAreaRenameTakesPendingTypingAlong()
{
    // The app's editors: Main open with its declarations above its ST body. Typing in the body
    // waits for a pause before it reaches the model; a rename in the table must not lose it.
    ProjectModel model;
    model.reset(sampleProject());
    const Project before = model.project();
    DocumentArea area(model);
    const BodyRef main {idOf(model, "Main"), BodyRef::Part::Pou, {}};
    QVERIFY(area.openBody(main));
    iec::editors::CodeEditor *body = area.textEditorFor(main);
    iec::editors::DeclarationEditor *declarations = area.declarationEditorFor(main);
    QVERIFY(body && declarations);
    body->moveCursor(QTextCursor::End);
    QTest::keyClick(body, Qt::Key_Return);
    QTest::keyClicks(body, QStringLiteral("Count := 7;"));
    QCOMPARE(model.body(main)->text(), kMainText); // still waiting for the pause

    iec::editors::DeclarationTableModel *table = declarations->tableModel();
    QVERIFY(table->setData(table->index(0, int(iec::editors::DeclarationColumn::Name)), QStringLiteral("Counter")));
    Project expected = before;
    countRenamedToCounter(expected);
    pouNamed(expected, QStringLiteral("Main")).bodies.front().setText(
        pouNamed(expected, QStringLiteral("Main")).body()->text() + QStringLiteral("\nCounter := 7;"));
    COMPARE_PROJECT(model.project(), expected);
    QCOMPARE(body->toPlainText(), expected.findPou(QStringLiteral("Main"))->body()->text());

    QUndoStack &stack = area.findChild<UndoStacks *>()->pouStack(main.pou);
    QCOMPARE(stack.count(), 1);
    stack.undo();
    QCOMPARE(model.body(main)->text(), kMainText + QStringLiteral("\nCount := 7;"));
    QCOMPARE(body->toPlainText(), model.body(main)->text());
    QCOMPARE(model.findVariable(main.pou, QStringLiteral("Count"))->name, QStringLiteral("Count"));
}

void TestVariableRename::freeNamesOnImport_data()
{
    QTest::addColumn<QStringList>("project");
    QTest::addColumn<QStringList>("imported");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("free name stays") << QStringList {QStringLiteral("A")} << QStringList {QStringLiteral("B")}
                                     << QStringList {QStringLiteral("B")};
    QTest::newRow("taken gets _1") << QStringList {QStringLiteral("A")} << QStringList {QStringLiteral("a")}
                                   << QStringList {QStringLiteral("a_1")};
    QTest::newRow("generated name never meets an imported one")
        << QStringList {QStringLiteral("A")} << QStringList {QStringLiteral("A"), QStringLiteral("A_1")}
        << QStringList {QStringLiteral("A_2"), QStringLiteral("A_1")};
    QTest::newRow("A_ edge: A_1, never A__1, and no clash with A's")
        << QStringList {QStringLiteral("A"), QStringLiteral("A_")} << QStringList {QStringLiteral("A"), QStringLiteral("A_")}
        << QStringList {QStringLiteral("A_1"), QStringLiteral("A_2")};
    QTest::newRow("numbers taken in the project are skipped")
        << QStringList {QStringLiteral("A"), QStringLiteral("A_1"), QStringLiteral("A_2")}
        << QStringList {QStringLiteral("A")} << QStringList {QStringLiteral("A_3")};
}

void TestVariableRename::freeNamesOnImport()
{
    QFETCH(QStringList, project);
    QFETCH(QStringList, imported);
    QFETCH(QStringList, expected);
    Project existing;
    for (const QString &name : project)
        existing.types.pous.push_back(stPou(name, PouKind::Program, {}));
    Project incoming;
    for (const QString &name : imported)
        incoming.types.pous.push_back(stPou(name, PouKind::Program, {}));
    ProjectModel model;
    model.reset(existing);
    ImportExport::Merge merge = ImportExport::merge(model, incoming);
    QVERIFY(merge.command);
    QUndoStack stack;
    stack.push(merge.command);
    QStringList added;
    for (size_t i = size_t(project.size()); i < model.project().types.pous.size(); ++i)
        added.append(model.project().types.pous[i].name);
    QCOMPARE(added, expected);
    // The one rule: what the project tree's own names would give.
    QCOMPARE(NameRules::firstFree(QStringLiteral("A_"), [](const QString &n) { return n == QLatin1String("A_"); }),
        QStringLiteral("A_1"));
}

namespace {

// An export of another project: its own Main (reading the global Alarm), a program Helper, and
// Config/Res with the globals Alarm and Speed, task Fast running Main as MainInst and task Slow.
Project importedProject()
{
    Project project;
    project.types.pous.push_back(stPou(QStringLiteral("Main"), PouKind::Program, QStringLiteral("Alarm := NOT Alarm;")));
    project.types.pous.push_back(stPou(QStringLiteral("Helper"), PouKind::Program, QStringLiteral("Speed := 1;")));
    Task fast;
    fast.name = QStringLiteral("Fast");
    fast.interval = QStringLiteral("T#10ms");
    fast.pouInstances.push_back(PouInstance {.name = QStringLiteral("MainInst"), .typeName = QStringLiteral("Main")});
    Task slow;
    slow.name = QStringLiteral("Slow");
    slow.pouInstances.push_back(PouInstance {.name = QStringLiteral("HelperInst"), .typeName = QStringLiteral("Helper")});
    Resource resource;
    resource.name = QStringLiteral("Res");
    resource.tasks = {fast, slow};
    resource.globalVars.push_back(VarList {.kind = VarListKind::Global,
        .variables = {variable(QStringLiteral("Alarm")), variable(QStringLiteral("Speed"), QStringLiteral("INT"))}});
    Configuration configuration;
    configuration.name = QStringLiteral("Config");
    configuration.resources.push_back(resource);
    project.instances.configurations.push_back(configuration);
    return project;
}

} // namespace

void TestVariableRename::importMergesConfigurations()
{
    ProjectModel model;
    model.reset(sampleProject());
    const Project before = model.project();
    ImportExport::Merge merge = ImportExport::merge(model, importedProject());
    QVERIFY(merge.command);
    QCOMPARE(merge.pous, 2);
    QCOMPARE(merge.configurations, 1);
    QUndoStack stack;
    stack.push(merge.command);
    QCOMPARE(stack.count(), 1);

    const auto check = [&] {
        const Project &now = model.project();
        QCOMPARE(now.types.pous.size(), before.types.pous.size() + 2);
        // Main clashed: the imported one is Main_1 and reads the renamed global Alarm_1.
        const Pou *importedMain = now.findPou(QStringLiteral("Main_1"));
        QVERIFY(importedMain);
        QCOMPARE(importedMain->body()->text(), QStringLiteral("Alarm_1 := NOT Alarm_1;"));
        QCOMPARE(now.findPou(QStringLiteral("Helper"))->body()->text(), QStringLiteral("Speed := 1;"));
        Instances expected = before.instances;
        Resource &resource = expected.configurations[0].resources[0];
        resource.globalVars.push_back(VarList {.kind = VarListKind::Global,
            .variables = {variable(QStringLiteral("Alarm_1")), variable(QStringLiteral("Speed"), QStringLiteral("INT"))}});
        Task fast;
        fast.name = QStringLiteral("Fast_1");
        fast.interval = QStringLiteral("T#10ms");
        fast.pouInstances.push_back(PouInstance {.name = QStringLiteral("MainInst_1"), .typeName = QStringLiteral("Main_1")});
        Task slow;
        slow.name = QStringLiteral("Slow");
        slow.pouInstances.push_back(PouInstance {.name = QStringLiteral("HelperInst"), .typeName = QStringLiteral("Helper")});
        resource.tasks.push_back(fast);
        resource.tasks.push_back(slow);
        QCOMPARE(now.instances, expected);
        // The project's own POUs are untouched.
        for (size_t i = 0; i < before.types.pous.size(); ++i)
            QCOMPARE(now.types.pous[i], before.types.pous[i]);
    };
    check();
    QStringList texts;
    for (const Message &message : merge.messages)
        texts.append(message.text);
    QVERIFY2(texts.contains(QStringLiteral("Main exists already; the imported one is named Main_1.")),
        qPrintable(texts.join(u'\n')));
    QVERIFY(texts.contains(QStringLiteral("Alarm exists already; the imported one is named Alarm_1.")));
    QVERIFY(texts.contains(QStringLiteral("Fast exists already in resource Res; the imported one is named Fast_1.")));
    QVERIFY(texts.contains(
        QStringLiteral("MainInst exists already in resource Res; the imported one is named MainInst_1.")));

    stack.undo();
    COMPARE_PROJECT(model.project(), before);
    stack.redo();
    check();
}

void TestVariableRename::importIntoOtherConfigurationOrNone()
{
    // A configuration of another name joins the project's first one (only that one runs).
    Project imported = importedProject();
    imported.instances.configurations[0].name = QStringLiteral("Plant");
    imported.instances.configurations[0].resources[0].name = QStringLiteral("Cpu");
    ConfigVariable located;
    located.instancePathAndName = QStringLiteral("Cpu.MainInst.Lamp");
    located.address = QStringLiteral("%QX0.0");
    imported.instances.configurations[0].configVars = ConfigVarList {.variables = {located}};
    {
        ProjectModel model;
        model.reset(sampleProject());
        ImportExport::Merge merge = ImportExport::merge(model, imported);
        std::unique_ptr<QUndoCommand> command(merge.command);
        command->redo();
        const std::vector<Configuration> &configurations = model.project().instances.configurations;
        QCOMPARE(configurations.size(), size_t(1));
        QCOMPARE(configurations[0].resources.size(), size_t(2));
        QCOMPARE(configurations[0].resources[1].name, QStringLiteral("Cpu"));
        QCOMPARE(configurations[0].resources[1].tasks[0].name, QStringLiteral("Fast")); // another resource: no clash
        QCOMPARE(configurations[0].resources[1].globalVars[0].variables[0].name, QStringLiteral("Alarm_1"));
        QCOMPARE(configurations[0].configVars, imported.instances.configurations[0].configVars); // VAR_CONFIG too
    }
    // A project without configurations takes them as they are.
    {
        ProjectModel model;
        model.reset(Project {});
        const Project before = model.project();
        ImportExport::Merge merge = ImportExport::merge(model, imported);
        std::unique_ptr<QUndoCommand> command(merge.command);
        command->redo();
        QCOMPARE(model.project().instances, imported.instances);
        command->undo();
        COMPARE_PROJECT(model.project(), before);
    }
}

QTEST_MAIN(TestVariableRename)
#include "tst_variablerename.moc"
