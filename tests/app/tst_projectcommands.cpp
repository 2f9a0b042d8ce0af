#include "app/addpoudialog.h"
#include "app/buildcontroller.h"
#include "app/addpoupartdialog.h"
#include "app/namerules.h"
#include "app/projectcommands.h"
#include "app/referencerename.h"
#include "app/renamedialog.h"
#include "model/projectmodel.h"
#include "tests/model/roundtrip.h"

#include <QComboBox>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QPushButton>
#include <QTest>
#include <QUndoStack>

#include <functional>

using namespace iec::app;
using namespace iec::model;
using iec::editors::EditorLanguage;

class TestProjectCommands : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void identifierRules_data();
    void identifierRules();
    void uniqueNames();
    void renameIdentifierInText_data();
    void renameIdentifierInText();
    void eachOperationRedoUndoRedo();
    void newBodiesStartAsTheirEditorOffers_data();
    void newBodiesStartAsTheirEditorOffers();
    void renameUpdatesReferencesInOneStep();
    void renamingAnActionOrTransitionUpdatesTheChart();
    void refusedOperationsChangeNothing_data();
    void refusedOperationsChangeNothing();
    void addPouDialogResult();
    void addPouDialogShowsWholeLanguageNames();
    void addPouPartDialogResult();
    void renameDialogValidates();
};

namespace {

Pou stPou(const QString &name, PouKind kind, const QString &text)
{
    Pou pou = makePou({.name = name, .kind = kind, .language = EditorLanguage::ST, .returnType = QStringLiteral("INT")});
    pou.bodies.front().setText(text);
    return pou;
}

// Main uses the function block Helper: an instance, a call, a member, a comment and a string.
Project sampleProject()
{
    Project project;
    project.types.pous.push_back(stPou(QStringLiteral("Helper"), PouKind::FunctionBlock, QStringLiteral("Out := In;")));
    Pou main = stPou(QStringLiteral("Main"), PouKind::Program,
        QStringLiteral("(* calls Helper *)\nh(In := 1);\nmsg := 'Helper';\nx := h.Out + HELPER_Limit;"));
    Variable instance;
    instance.name = QStringLiteral("h");
    instance.type.kind = DerivedType {.name = QStringLiteral("Helper")};
    main.pouInterface->varLists.push_back(VarList {.variables = {instance}});
    main.actions.push_back(PouPart {.name = QStringLiteral("Reset"), .body = Body::withLanguage(BodyLanguage::IL)});
    main.actions.back().body.setText(QStringLiteral("CAL Helper\nLD helper.Out"));
    PouPart diagram {.name = QStringLiteral("Diagram"), .body = Body::withLanguage(BodyLanguage::FBD)};
    Block call;
    call.localId = 1;
    call.typeName = QStringLiteral("HELPER");
    call.instanceName = QStringLiteral("h");
    Block timer;
    timer.localId = 2;
    timer.typeName = QStringLiteral("TON");
    diagram.body.elements()->push_back(call);
    diagram.body.elements()->push_back(timer);
    main.actions.push_back(diagram);
    project.types.pous.push_back(main);
    return project;
}

struct Fixture {
    ProjectModel model;
    QUndoStack stack;
    ProjectCommands commands {model, stack};

    Fixture() { model.reset(sampleProject()); }
    [[nodiscard]] PouId idOf(const QString &name) const { return model.project().findPou(name)->id; }
};

// One line per element of a body, in order: "Step Init initial", "Transition TRUE", "Jump Init";
// a text body gives its text.
QStringList bodyOutline(const Body &body)
{
    if (!body.elements())
        return {QStringLiteral("text ") + body.text()};
    QStringList lines;
    for (const Element &element : *body.elements()) {
        if (const auto *step = std::get_if<Step>(&element))
            lines << QStringLiteral("Step %1%2").arg(step->name, step->initialStep ? QStringLiteral(" initial") : QString());
        else if (const auto *transition = std::get_if<Transition>(&element)) {
            const auto *inlined = transition->condition ? std::get_if<InlineCondition>(&transition->condition->kind) : nullptr;
            lines << QStringLiteral("Transition ") + (inlined ? inlined->body->text() : QStringLiteral("?"));
        } else if (const auto *jump = std::get_if<JumpStep>(&element))
            lines << QStringLiteral("Jump ") + jump->targetName;
        else
            lines << QStringLiteral("other");
    }
    return lines;
}

} // namespace

void TestProjectCommands::newBodiesStartAsTheirEditorOffers_data()
{
    // Issue 13: a new SFC POU opened on an empty canvas with no hint, and saved an empty chart.
    // It starts as in CODESYS: the initial step Init, a transition TRUE, a jump back to Init.
    QTest::addColumn<int>("part"); // BodyRef::Part
    QTest::addColumn<int>("language");
    QTest::addColumn<QStringList>("outline");
    const QStringList chart {QStringLiteral("Step Init initial"), QStringLiteral("Transition TRUE"), QStringLiteral("Jump Init")};
    QTest::newRow("SFC program") << int(BodyRef::Part::Pou) << int(EditorLanguage::SFC) << chart;
    QTest::newRow("SFC action") << int(BodyRef::Part::Action) << int(EditorLanguage::SFC) << chart;
    QTest::newRow("ST program") << int(BodyRef::Part::Pou) << int(EditorLanguage::ST) << QStringList {QStringLiteral("text ")};
    QTest::newRow("LD action") << int(BodyRef::Part::Action) << int(EditorLanguage::LD) << QStringList {};
    QTest::newRow("FBD program") << int(BodyRef::Part::Pou) << int(EditorLanguage::FBD) << QStringList {};
    QTest::newRow("CFC program") << int(BodyRef::Part::Pou) << int(EditorLanguage::CFC) << QStringList {};
    QTest::newRow("CFC action") << int(BodyRef::Part::Action) << int(EditorLanguage::CFC) << QStringList {};
}

void TestProjectCommands::newBodiesStartAsTheirEditorOffers()
{
    QFETCH(int, part);
    QFETCH(int, language);
    QFETCH(QStringList, outline);
    ProjectModel model;
    Project start;
    start.types.pous.push_back(makePou({.name = QStringLiteral("Main"), .language = EditorLanguage::ST}));
    model.reset(start);
    QUndoStack stack;
    ProjectCommands commands {model, stack};
    const Project before = model.project();
    const PouId main = model.project().types.pous.front().id;

    QString error;
    const Body *body = nullptr;
    if (BodyRef::Part(part) == BodyRef::Part::Pou) {
        const std::optional<PouId> id = commands.addPou({.name = QStringLiteral("Chart"), .language = EditorLanguage(language)}, &error);
        QVERIFY2(id, qPrintable(error));
        body = model.body({*id, BodyRef::Part::Pou, {}});
    } else {
        const std::optional<BodyRef> ref = commands.addPouPart(main,
            {.part = BodyRef::Part(part), .name = QStringLiteral("Sequence"), .language = EditorLanguage(language)}, &error);
        QVERIFY2(ref, qPrintable(error));
        body = model.body(*ref);
    }
    QVERIFY(body);
    QCOMPARE(bodyOutline(*body), outline);
    QCOMPARE(int(iec::editors::editorLanguage(*body)), language); // a CFC opens in the CFC editor
    // Valid as it is: the file validates and the build finds nothing to complain about.
    QCOMPARE(iec::test::savedSchemaErrors(model.project()), QString());
    for (const Message &message : compileMessages(model.project()))
        QVERIFY2(message.severity == Message::Severity::Info, qPrintable(message.text));
    // One step: undo takes the POU or action away with its chart.
    QCOMPARE(stack.count(), 1);
    stack.undo();
    QVERIFY(model.project() == before);
}

void TestProjectCommands::identifierRules_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("valid");
    QTest::newRow("letters") << QStringLiteral("Main") << true;
    QTest::newRow("digits and underscores") << QStringLiteral("Tank_2_Level") << true;
    QTest::newRow("leading underscore") << QStringLiteral("_Hidden") << true;
    QTest::newRow("empty") << QString() << false;
    QTest::newRow("leading digit") << QStringLiteral("2Tank") << false;
    QTest::newRow("double underscore") << QStringLiteral("Tank__Level") << false;
    QTest::newRow("trailing underscore") << QStringLiteral("Tank_") << false;
    QTest::newRow("space") << QStringLiteral("Tank Level") << false;
    QTest::newRow("umlaut") << QStringLiteral("Pumpe\u00fc") << false;
    QTest::newRow("keyword") << QStringLiteral("end_if") << false;
    QTest::newRow("type name") << QStringLiteral("INT") << false;
}

void TestProjectCommands::identifierRules()
{
    QFETCH(QString, name);
    QFETCH(bool, valid);
    QCOMPARE(NameRules::isIdentifier(name), valid);
}

void TestProjectCommands::uniqueNames()
{
    Fixture fixture;
    const Project &project = fixture.model.project();
    QCOMPARE(NameRules::uniquePouName(project, QStringLiteral("Valve")), QStringLiteral("Valve"));
    QCOMPARE(NameRules::uniquePouName(project, QStringLiteral("helper")), QStringLiteral("helper_1"));
    QVERIFY(NameRules::pouNameError(project, QStringLiteral("MAIN")).has_value()); // case-insensitive
    QVERIFY(!NameRules::pouNameError(project, QStringLiteral("MAIN"), fixture.idOf(QStringLiteral("Main"))));
    const PouId main = fixture.idOf(QStringLiteral("Main"));
    QCOMPARE(NameRules::uniquePartName(project, main, QStringLiteral("Reset")), QStringLiteral("Reset_1"));
    QVERIFY(NameRules::partNameError(project, main, QStringLiteral("reset")).has_value());
    QVERIFY(!NameRules::partNameError(project, main, QStringLiteral("reset"), QStringLiteral("Reset")));
}

void TestProjectCommands::renameIdentifierInText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    QTest::newRow("call") << QStringLiteral("Helper(In := 1);") << QStringLiteral("Pump(In := 1);");
    QTest::newRow("case-insensitive") << QStringLiteral("x := HELPER(1);") << QStringLiteral("x := Pump(1);");
    QTest::newRow("longer names stay") << QStringLiteral("Helper_2 := MyHelper;")
                                       << QStringLiteral("Helper_2 := MyHelper;");
    QTest::newRow("comments stay") << QStringLiteral("(* Helper *) // Helper\nHelper();")
                                   << QStringLiteral("(* Helper *) // Helper\nPump();");
    QTest::newRow("strings stay") << QStringLiteral("s := 'Helper'; w := \"Helper\";")
                                  << QStringLiteral("s := 'Helper'; w := \"Helper\";");
    QTest::newRow("members stay") << QStringLiteral("x := fb.Helper + Helper.y;")
                                  << QStringLiteral("x := fb.Helper + Pump.y;");
    QTest::newRow("IL operand") << QStringLiteral("CAL Helper\nLD Helper.Q") << QStringLiteral("CAL Pump\nLD Pump.Q");
    QTest::newRow("nothing to do") << QStringLiteral("x := 1;") << QStringLiteral("x := 1;");
}

void TestProjectCommands::renameIdentifierInText()
{
    QFETCH(QString, text);
    QFETCH(QString, expected);
    QCOMPARE(renameIdentifier(text, QStringLiteral("Helper"), QStringLiteral("Pump")), expected);
}

void TestProjectCommands::eachOperationRedoUndoRedo()
{
    // Each operation is one undo step: undo gives back the project exactly, redo the result exactly.
    struct Operation {
        const char *name;
        std::function<bool(Fixture &)> run;
        std::function<void(const Project &)> check;
    };
    const std::vector<Operation> operations = {
        {"add ST program",
            [](Fixture &f) {
                return f.commands.addPou({.name = QStringLiteral("Conveyor"), .language = EditorLanguage::ST})
                    .has_value();
            },
            [](const Project &p) {
                QCOMPARE(p.types.pous.size(), std::size_t(3));
                QCOMPARE(p.types.pous.back().name, QStringLiteral("Conveyor"));
                QCOMPARE(p.types.pous.back().kind, PouKind::Program);
                QCOMPARE(p.types.pous.back().language(), BodyLanguage::ST);
            }},
        {"add function",
            [](Fixture &f) {
                return f.commands
                    .addPou({.name = QStringLiteral("Scale"),
                        .kind = PouKind::Function,
                        .language = EditorLanguage::IL,
                        .returnType = QStringLiteral("real")})
                    .has_value();
            },
            [](const Project &p) {
                const Pou &scale = p.types.pous.back();
                QCOMPARE(scale.kind, PouKind::Function);
                QCOMPARE(scale.language(), BodyLanguage::IL);
                QVERIFY(scale.pouInterface->returnType == DataType {ElementaryType {QStringLiteral("REAL")}});
            }},
        {"add action",
            [](Fixture &f) {
                return f.commands
                    .addPouPart(f.idOf(QStringLiteral("Helper")),
                        {.part = BodyRef::Part::Action, .name = QStringLiteral("Init"), .language = EditorLanguage::LD})
                    .has_value();
            },
            [](const Project &p) {
                QCOMPARE(p.types.pous.front().actions.size(), std::size_t(1));
                QCOMPARE(p.types.pous.front().actions.front().name, QStringLiteral("Init"));
                QCOMPARE(p.types.pous.front().actions.front().body.language(), BodyLanguage::LD);
            }},
        {"add transition",
            [](Fixture &f) {
                return f.commands
                    .addPouPart(f.idOf(QStringLiteral("Main")),
                        {.part = BodyRef::Part::Transition,
                            .name = QStringLiteral("Done"),
                            .language = EditorLanguage::ST})
                    .has_value();
            },
            [](const Project &p) { QCOMPARE(p.types.pous.back().transitions.front().name, QStringLiteral("Done")); }},
        {"rename action",
            [](Fixture &f) {
                return f.commands.rename(
                    {f.idOf(QStringLiteral("Main")), BodyRef::Part::Action, QStringLiteral("Reset")},
                    QStringLiteral("Clear"));
            },
            [](const Project &p) { QCOMPARE(p.types.pous.back().actions.front().name, QStringLiteral("Clear")); }},
        {"duplicate POU",
            [](Fixture &f) {
                return f.commands.duplicate({f.idOf(QStringLiteral("Helper")), {}, {}}).has_value();
            },
            [](const Project &p) {
                QCOMPARE(p.types.pous.size(), std::size_t(3));
                QCOMPARE(p.types.pous[1].name, QStringLiteral("Helper_1")); // right after the original
                QVERIFY(p.types.pous[1].bodies == p.types.pous[0].bodies);
            }},
        {"duplicate action",
            [](Fixture &f) {
                return f.commands
                    .duplicate({f.idOf(QStringLiteral("Main")), BodyRef::Part::Action, QStringLiteral("Reset")})
                    .has_value();
            },
            [](const Project &p) {
                QCOMPARE(p.types.pous.back().actions.size(), std::size_t(3));
                QCOMPARE(p.types.pous.back().actions.back().name, QStringLiteral("Reset_1"));
            }},
        {"delete POU",
            [](Fixture &f) {
                return f.commands.remove({f.idOf(QStringLiteral("Helper")), {}, {}});
            },
            [](const Project &p) {
                QCOMPARE(p.types.pous.size(), std::size_t(1));
                QCOMPARE(p.types.pous.front().name, QStringLiteral("Main"));
            }},
        {"delete action",
            [](Fixture &f) {
                return f.commands.remove(
                    {f.idOf(QStringLiteral("Main")), BodyRef::Part::Action, QStringLiteral("Reset")});
            },
            [](const Project &p) { QCOMPARE(p.types.pous.back().actions.size(), std::size_t(1)); }},
    };
    for (const Operation &operation : operations) {
        Fixture fixture;
        const Project before = fixture.model.project();
        QVERIFY2(operation.run(fixture), operation.name);
        QCOMPARE(fixture.stack.count(), 1);
        const Project after = fixture.model.project();
        operation.check(after);
        if (QTest::currentTestFailed())
            QFAIL(operation.name);

        fixture.stack.undo();
        QVERIFY2(fixture.model.project() == before, operation.name);
        fixture.stack.redo();
        QVERIFY2(fixture.model.project() == after, operation.name);
        fixture.stack.undo();
        QVERIFY2(fixture.model.project() == before, operation.name);
    }
}

void TestProjectCommands::renameUpdatesReferencesInOneStep()
{
    Fixture fixture;
    const Project before = fixture.model.project();
    const PouId helper = fixture.idOf(QStringLiteral("Helper"));
    QString error;
    QVERIFY2(fixture.commands.rename({helper, {}, {}}, QStringLiteral("Pump"), &error), qPrintable(error));
    QCOMPARE(fixture.stack.count(), 1);

    const Project &after = fixture.model.project();
    QCOMPARE(after.findPou(helper)->name, QStringLiteral("Pump"));
    const Pou &main = *after.findPou(QStringLiteral("Main"));
    QCOMPARE(main.body()->text(),
        QStringLiteral("(* calls Helper *)\nh(In := 1);\nmsg := 'Helper';\nx := h.Out + HELPER_Limit;"));
    QCOMPARE(main.actions.front().body.text(), QStringLiteral("CAL Pump\nLD Pump.Out"));
    const std::vector<Element> &elements = *main.actions.back().body.elements();
    QCOMPARE(std::get<Block>(elements[0]).typeName, QStringLiteral("Pump"));
    QCOMPARE(std::get<Block>(elements[1]).typeName, QStringLiteral("TON"));
    QVERIFY(main.pouInterface->varLists.front().variables.front().type
        == DataType {DerivedType {.name = QStringLiteral("Pump")}});
    const Project renamed = after;

    // A program's rename reaches the tasks that run it, in the same step.
    Project withTask = fixture.model.project();
    withTask.instances.configurations.push_back(Configuration {.name = QStringLiteral("Plc")});
    withTask.instances.configurations.back().resources.push_back(Resource {.name = QStringLiteral("Cpu")});
    withTask.instances.configurations.back().resources.back().tasks.push_back(
        Task {.name = QStringLiteral("Cyclic"), .pouInstances = {PouInstance {.name = QStringLiteral("Run"), .typeName = QStringLiteral("MAIN")}}});
    ProjectModel programModel;
    programModel.reset(withTask);
    QUndoStack programStack;
    ProjectCommands programCommands {programModel, programStack};
    const PouId mainId = programModel.project().findPou(QStringLiteral("Main"))->id;
    QVERIFY(programCommands.rename({mainId, {}, {}}, QStringLiteral("Plant"), &error));
    QCOMPARE(programStack.count(), 1);
    QCOMPARE(programModel.project().instances.configurations.front().resources.front().tasks.front().pouInstances.front().typeName,
        QStringLiteral("Plant"));
    programStack.undo();
    QCOMPARE(programModel.project().instances.configurations.front().resources.front().tasks.front().pouInstances.front().typeName,
        QStringLiteral("MAIN"));

    fixture.stack.undo();
    QVERIFY(fixture.model.project() == before);
    fixture.stack.redo();
    QVERIFY(fixture.model.project() == renamed);
}

void TestProjectCommands::renamingAnActionOrTransitionUpdatesTheChart()
{
    // A chart whose action block names action Fill twice and whose transition names Full; an ST
    // action calls Fill.
    Project project;
    Pou chart = makePou({.name = QStringLiteral("Chart"), .language = EditorLanguage::SFC});
    chart.bodies = {Body::withLanguage(BodyLanguage::SFC)}; // this chart only, not the new one's Init
    ActionBlock block;
    block.localId = 2;
    block.actions.push_back({.localId = 0, .qualifier = QStringLiteral("N"), .reference = Reference {QStringLiteral("Fill")}});
    block.actions.push_back({.localId = 1, .qualifier = QStringLiteral("P1"), .reference = Reference {QStringLiteral("Drain")}});
    block.actions.push_back({.localId = 2, .qualifier = QStringLiteral("P0"), .reference = Reference {QStringLiteral("FILL")}});
    Transition transition;
    transition.localId = 3;
    transition.condition = Condition {.kind = Reference {QStringLiteral("Full")}};
    chart.bodies.front().elements()->push_back(block);
    chart.bodies.front().elements()->push_back(transition);
    for (const char *name : {"Fill", "Drain"}) {
        chart.actions.push_back(PouPart {.name = QString::fromLatin1(name), .body = Body::withLanguage(BodyLanguage::ST)});
    }
    chart.actions.back().body.setText(QStringLiteral("Fill; (* Fill *)"));
    chart.transitions.push_back(PouPart {.name = QStringLiteral("Full"), .body = Body::withLanguage(BodyLanguage::ST)});
    project.types.pous.push_back(chart);
    ProjectModel model;
    model.reset(project);
    QUndoStack stack;
    ProjectCommands commands {model, stack};
    const PouId id = model.project().types.pous.front().id;
    const Project before = model.project();

    QString error;
    QVERIFY2(commands.rename({id, BodyRef::Part::Action, QStringLiteral("Fill")}, QStringLiteral("Top_up"), &error),
        qPrintable(error));
    QCOMPARE(stack.count(), 1);
    const Pou &renamed = *model.project().findPou(id);
    const auto &actions = std::get<ActionBlock>(renamed.bodies.front().elements()->at(0)).actions;
    QCOMPARE(actions[0].reference->name, QStringLiteral("Top_up"));
    QCOMPARE(actions[1].reference->name, QStringLiteral("Drain"));
    QCOMPARE(actions[2].reference->name, QStringLiteral("Top_up"));
    QCOMPARE(renamed.actions.front().name, QStringLiteral("Top_up"));
    QCOMPARE(renamed.actions.back().body.text(), QStringLiteral("Top_up; (* Fill *)"));

    QVERIFY2(commands.rename({id, BodyRef::Part::Transition, QStringLiteral("Full")}, QStringLiteral("Is_full"), &error),
        qPrintable(error));
    const auto &condition = std::get<Transition>(model.project().findPou(id)->bodies.front().elements()->at(1)).condition;
    QCOMPARE(std::get<Reference>(condition->kind).name, QStringLiteral("Is_full"));

    stack.undo();
    stack.undo();
    QVERIFY(model.project() == before);
    stack.redo();
    QCOMPARE(model.project().findPou(id)->actions.back().body.text(), QStringLiteral("Top_up; (* Fill *)"));
}

void TestProjectCommands::refusedOperationsChangeNothing_data()
{
    QTest::addColumn<QString>("newName");
    QTest::newRow("clash with a POU") << QStringLiteral("main");
    QTest::newRow("not an identifier") << QStringLiteral("1st");
    QTest::newRow("keyword") << QStringLiteral("WHILE");
    QTest::newRow("empty") << QString();
}

void TestProjectCommands::refusedOperationsChangeNothing()
{
    QFETCH(QString, newName);
    Fixture fixture;
    const Project before = fixture.model.project();
    QString error;
    QVERIFY(!fixture.commands.rename({fixture.idOf(QStringLiteral("Helper")), {}, {}}, newName, &error));
    QVERIFY(!error.isEmpty());
    error.clear();
    QVERIFY(!fixture.commands.addPou({.name = newName}, &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(fixture.model.project() == before);
    QCOMPARE(fixture.stack.count(), 0);
}

void TestProjectCommands::addPouDialogShowsWholeLanguageNames()
{
    // Issue 13: "Sequential Function Chart (SFC)" was elided. Every choice fits its box when the
    // dialog opens at its own size.
    Fixture fixture;
    AddPouDialog dialog(fixture.model.project());
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    for (const char *name : {"kind", "language"}) {
        auto *combo = dialog.findChild<QComboBox *>(QString::fromLatin1(name));
        for (int index = 0; index < combo->count(); ++index) {
            QStyleOptionComboBox option;
            option.initFrom(combo);
            option.currentText = combo->itemText(index);
            option.currentIcon = combo->itemIcon(index);
            option.iconSize = combo->iconSize();
            const QRect field = combo->style()->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, combo);
            const int needed = combo->fontMetrics().horizontalAdvance(combo->itemText(index))
                + (combo->itemIcon(index).isNull() ? 0 : combo->iconSize().width() + 4);
            QVERIFY2(field.width() >= needed, qPrintable(QStringLiteral("%1: %2 < %3").arg(combo->itemText(index)).arg(field.width()).arg(needed)));
        }
    }
}

void TestProjectCommands::addPouDialogResult()
{
    Fixture fixture;
    AddPouDialog dialog(fixture.model.project());
    auto *name = dialog.findChild<QLineEdit *>(QStringLiteral("name"));
    auto *kind = dialog.findChild<QComboBox *>(QStringLiteral("kind"));
    auto *language = dialog.findChild<QComboBox *>(QStringLiteral("language"));
    auto *returnType = dialog.findChild<QComboBox *>(QStringLiteral("returnType"));
    QPushButton *ok = dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    QCOMPARE(name->text(), QStringLiteral("POU")); // a free default
    QVERIFY(ok->isEnabled());
    QVERIFY(!returnType->isEnabled());

    name->setText(QStringLiteral("helper"));
    QVERIFY(!ok->isEnabled());
    QVERIFY(!dialog.problem().isEmpty());
    name->setText(QStringLiteral("Limit"));
    kind->setCurrentIndex(kind->findData(int(PouKind::Function)));
    language->setCurrentIndex(language->findData(int(EditorLanguage::IL)));
    QVERIFY(returnType->isEnabled());
    returnType->setCurrentText(QStringLiteral("LREAL"));
    QVERIFY(ok->isEnabled());
    const NewPou result = dialog.newPou();
    QCOMPARE(result.name, QStringLiteral("Limit"));
    QCOMPARE(result.kind, PouKind::Function);
    QCOMPARE(result.language, EditorLanguage::IL);
    QCOMPARE(result.returnType, QStringLiteral("LREAL"));

    returnType->setCurrentText(QString());
    QVERIFY(!ok->isEnabled());
}

void TestProjectCommands::addPouPartDialogResult()
{
    Fixture fixture;
    AddPouPartDialog dialog(fixture.model.project(), fixture.idOf(QStringLiteral("Main")), BodyRef::Part::Transition);
    auto *name = dialog.findChild<QLineEdit *>(QStringLiteral("name"));
    QPushButton *ok = dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    QCOMPARE(name->text(), QStringLiteral("Transition"));
    name->setText(QStringLiteral("RESET")); // an action of Main has that name
    QVERIFY(!ok->isEnabled());
    name->setText(QStringLiteral("Full"));
    dialog.findChild<QComboBox *>(QStringLiteral("language"))->setCurrentIndex(1);
    QVERIFY(ok->isEnabled());
    const NewPouPart part = dialog.newPart();
    QCOMPARE(part.part, BodyRef::Part::Transition);
    QCOMPARE(part.name, QStringLiteral("Full"));
    QCOMPARE(part.language, EditorLanguage::IL);
}

void TestProjectCommands::renameDialogValidates()
{
    Fixture fixture;
    const PouId helper = fixture.idOf(QStringLiteral("Helper"));
    RenameDialog dialog(QStringLiteral("Helper"),
        [&](const QString &name) { return NameRules::pouNameError(fixture.model.project(), name, helper); });
    auto *name = dialog.findChild<QLineEdit *>(QStringLiteral("name"));
    QPushButton *ok = dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    QVERIFY(!ok->isEnabled()); // unchanged
    name->setText(QStringLiteral("Main"));
    QVERIFY(!ok->isEnabled());
    QVERIFY(!dialog.problem().isEmpty());
    name->setText(QStringLiteral(" Pump "));
    QVERIFY(ok->isEnabled());
    QCOMPARE(dialog.newName(), QStringLiteral("Pump"));
}

QTEST_MAIN(TestProjectCommands)
#include "tst_projectcommands.moc"
