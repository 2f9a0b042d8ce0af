// The SFC editor driven as a user drives it: the mixing-tank chart of seed 001 built with editor
// commands only, saved and read back, every command undone and redone to the exact model state,
// the online overlay from a snapshot, and pictures of the chart for looking at.
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/sfc/sfceditor.h"
#include "editors/sfc/sfcitems.h"
#include "interpreter/runtime/snapshot.h"
#include "model/body.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"
#include "model/sfcoptions.h"
#include "tests/editors/sfcmixingtank.h"
#include "tests/model/roundtrip.h"
#include "tests/editors/languageswitch.h"

#include <QAction>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>

using namespace iec;
using namespace iec::editors::sfc;
using model::BodyRef;
using model::Element;
using iec::tests::transitionAfter;

namespace {

model::Project projectWithEmptyChart()
{
    model::Project project;
    project.fileHeader = {.companyName = QStringLiteral("IEC Studio tests"), .productName = QStringLiteral("IEC Studio"),
        .productVersion = QStringLiteral("1"), .creationDateTime = QStringLiteral("2026-01-01T00:00:00")};
    project.contentHeader.name = QStringLiteral("MixingTank");
    model::Pou pou;
    pou.name = QStringLiteral("Tank");
    pou.kind = model::PouKind::Program;
    pou.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::SFC));
    project.types.pous.push_back(pou);
    return project;
}

std::vector<Element> elementsOf(const model::ProjectModel &model, const BodyRef &ref)
{
    return *model.body(ref)->elements();
}

QString shotDir()
{
    const QString dir = qEnvironmentVariable("IEC_SHOT_DIR", QDir::tempPath() + QStringLiteral("/iec-sfc-shots"));
    QDir().mkpath(dir);
    return dir;
}

QString conditionOf(const SfcEditor &editor, quint64 transitionId)
{
    const ChartDocument doc = editor.document();
    const Element *e = doc.element(transitionId);
    const auto &condition = std::get<model::Transition>(*e).condition;
    return std::get<model::InlineCondition>(condition->kind).body->text();
}

} // namespace

class TestSfcEditor : public QObject
{
    Q_OBJECT

private:
    struct Fixture;
    static model::Pou pouOf(const Fixture &f) { return *f.model.project().findPou(f.ref.pou); }
    struct Fixture {
        model::ProjectModel model;
        QUndoStack stack;
        BodyRef ref;
        std::unique_ptr<SfcEditor> editor;
        std::vector<model::Pou> states; // after each command, states[0] before any
        bool validate = false; // every command's result saved and checked against the XSD

        Fixture()
        {
            model.reset(projectWithEmptyChart());
            ref = BodyRef {model.project().types.pous.front().id};
            editor = std::make_unique<SfcEditor>(model, ref, &stack);
            editor->resize(900, 900);
            states.push_back(*model.project().findPou(ref.pou));
        }
        // Runs one editor command; it must succeed and add exactly one undo step.
        void run(const char *what, const std::function<bool()> &command)
        {
            const int before = stack.count();
            QVERIFY2(command(), qPrintable(QStringLiteral("%1: %2").arg(QLatin1String(what), editor->lastMessage())));
            QVERIFY2(stack.count() == before + 1, what);
            states.push_back(*model.project().findPou(ref.pou));
            if (validate) {
                const QString errors = test::savedSchemaErrors(model.project());
                QVERIFY2(errors.isEmpty(), qPrintable(QStringLiteral("after %1:\n%2").arg(QLatin1String(what), errors)));
            }
        }
    };

    // Builds the mixing tank (sfcmixingtank.h) with Mix.T >= T#5s, each command one undo step.
    static void buildMixingTank(Fixture &f)
    {
        tests::buildMixingTank(*f.editor, "Mix.T >= T#5s",
            [&f](const char *what, const std::function<bool()> &command) { f.run(what, command); });
    }

private Q_SLOTS:
    void mixingTankIsBuiltWithEditorCommands()
    {
        Fixture f;
        buildMixingTank(f);
        const ChartDocument doc = f.editor->document();
        QStringList steps;
        for (const Element &element : doc.elements)
            if (const auto *step = std::get_if<model::Step>(&element))
                steps << step->name + (step->initialStep ? QStringLiteral("*") : QString());
        QCOMPARE(steps, (QStringList {QStringLiteral("Init*"), QStringLiteral("Fill_A"), QStringLiteral("Fill_B"),
                            QStringLiteral("Mix"), QStringLiteral("Drain")}));
        // The structure: Init, T, Fill_A, T, Fill_B, T, Mix, T, Drain, selection of two jumps.
        const Sequence &main = doc.chart.main;
        QCOMPARE(main.size(), std::size_t(10));
        QCOMPARE(main.back().kind, NodeKind::Selection);
        QCOMPARE(main.back().branches.size(), std::size_t(2));
        QCOMPARE(main.back().convergenceId, quint64(0));
        QCOMPARE(main.back().branches[0].back().kind, NodeKind::Jump);
        QCOMPARE(std::get<model::JumpStep>(*doc.element(main.back().branches[0].back().localId)).targetName, QStringLiteral("Fill_A"));
        QCOMPARE(std::get<model::JumpStep>(*doc.element(main.back().branches[1].back().localId)).targetName, QStringLiteral("Init"));
        QCOMPARE(conditionOf(*f.editor, main[1].localId), QStringLiteral("SB1"));
        QCOMPARE(conditionOf(*f.editor, main[7].localId), QStringLiteral("Mix.T >= T#5s"));
        const auto actions = stepActions(doc, f.editor->stepId(QStringLiteral("Mix")));
        QCOMPARE(actions.size(), std::size_t(1));
        QCOMPARE(actions.front().reference->name, QStringLiteral("M"));
        // Laid out top-down in one column: every step below the one before, same axis.
        double lastY = -1;
        for (const QString &name : {QStringLiteral("Init"), QStringLiteral("Fill_A"), QStringLiteral("Fill_B"),
                 QStringLiteral("Mix"), QStringLiteral("Drain")}) {
            const QRectF rect = f.editor->scene()->itemFor(f.editor->stepId(name))->boundingRect();
            QVERIFY2(rect.top() > lastY, qPrintable(name));
            lastY = rect.bottom();
        }
        // Nothing overlaps: no two element frames intersect.
        QList<QRectF> frames;
        for (editors::DiagramItem *item : f.editor->scene()->diagramItems())
            frames << static_cast<SfcItem *>(item)->frame();
        for (qsizetype i = 0; i < frames.size(); ++i)
            for (qsizetype j = i + 1; j < frames.size(); ++j)
                QVERIFY2(!frames[i].intersects(frames[j]), qPrintable(QStringLiteral("%1 / %2").arg(i).arg(j)));
    }

    void savedAndReloadedToTheSameModel()
    {
        Fixture f;
        buildMixingTank(f);
        const QByteArray bytes = model::plcopen::writeProject(f.model.project());
        const model::plcopen::ReadResult read = model::plcopen::readProject(bytes);
        QVERIFY(read.ok);
        const model::Pou *reloaded = read.project.findPou(QStringLiteral("Tank"));
        QVERIFY(reloaded);
        QCOMPARE(reloaded->bodies.size(), std::size_t(1));
        QVERIFY(reloaded->bodies.front() == *f.model.body(f.ref));
        // And the editor reads the same structure from it.
        QVERIFY(readChart(*reloaded->bodies.front().elements()).chart == f.editor->document().chart);
    }

    // Every command of the editor after the mixing tank: branches both ways, steps before and
    // after, a macro step and a step inside it, jumps, actions, step options with entry/exit and
    // a simplified step's active action, conditions inline, by name and in place, a priority,
    // copy/paste, cut, delete, Arrange Chart.
    static void applyEveryCommand(Fixture &f)
    {
        SfcEditor &e = *f.editor;
        const quint64 mix = e.stepId(QStringLiteral("Mix"));
        e.select({mix});
        f.run("parallel branch", [&] { return e.trigger(QStringLiteral("sfcParRight")); });
        const quint64 stirrer = e.selection().front();
        e.select({stirrer});
        f.run("step after in the branch", [&] { return e.trigger(QStringLiteral("sfcStepAfter")); });
        e.select({e.stepId(QStringLiteral("Fill_B"))});
        f.run("step before", [&] { return e.trigger(QStringLiteral("sfcStepBefore")); });
        f.run("macro step", [&] { return e.trigger(QStringLiteral("sfcMacro")); });
        const quint64 fillA = e.stepId(QStringLiteral("Fill_A"));
        f.run("second action", [&] { return e.edit(QStringLiteral("Add action"), [&](ChartDocument &d, const auto &) { return addAction(d, fillA, actionAssociation(QStringLiteral("L"), QStringLiteral("Horn"), QStringLiteral("T#2s"))); }); });
        f.run("change action", [&] { return e.edit(QStringLiteral("Change action"), [&](ChartDocument &d, const auto &) { return changeAction(d, fillA, 1, actionAssociation(QStringLiteral("D"), QStringLiteral("Horn"), QStringLiteral("T#1s"), QStringLiteral("HornOn"))); }); });
        f.run("move action", [&] { return e.edit(QStringLiteral("Move action"), [&](ChartDocument &d, const auto &) { return moveAction(d, fillA, 1, 0); }); });
        f.run("remove action", [&] { return e.edit(QStringLiteral("Remove action"), [&](ChartDocument &d, const auto &) { return removeAction(d, fillA, 0); }); });
        StepProperties options = *stepProperties(e.document(), e.stepId(QStringLiteral("Init")));
        options.options.entryAction = QStringLiteral("ResetAll");
        options.options.maxTime = QStringLiteral("T#1m");
        options.comment = QStringLiteral("Waits for the start button");
        f.run("step options", [&] { return e.edit(QStringLiteral("Change step"), [&](ChartDocument &d, const auto &) { return setStepProperties(d, e.stepId(QStringLiteral("Init")), options); }); });
        const quint64 afterInit = transitionAfter(e, e.stepId(QStringLiteral("Init")));
        f.run("priority", [&] { return e.edit(QStringLiteral("Change priority"), [&](ChartDocument &d, const auto &) { return setPriority(d, afterInit, 1); }); });
        f.run("named transition", [&] { return e.edit(QStringLiteral("Change condition"), [&](ChartDocument &d, const auto &) { return setConditionReference(d, afterInit, QStringLiteral("StartPressed")); }); });
        const quint64 fillB = e.stepId(QStringLiteral("Fill_B"));
        e.select({fillB, transitionAfter(e, fillB)});
        QVERIFY(e.trigger(QStringLiteral("sfcCopy")));
        e.select({transitionAfter(e, fillB)});
        f.run("paste", [&] { return e.trigger(QStringLiteral("sfcPaste")); });
        QVERIFY(e.stepId(QStringLiteral("Fill_B_1")));
        f.run("delete", [&] { return e.trigger(QStringLiteral("sfcDelete")); });
        e.select({e.stepId(QStringLiteral("Drain"))});
        f.run("alternative left", [&] {
            const quint64 t = transitionAfter(e, e.stepId(QStringLiteral("Fill_B")));
            e.select({t});
            return e.trigger(QStringLiteral("sfcAltLeft"));
        });
        const quint64 fresh = e.selection().front();
        e.select({fresh});
        f.run("step in the new branch", [&] { return e.trigger(QStringLiteral("sfcStepAfter")); });
        const quint64 branchStep = e.selection().front();
        f.run("delete the new branch", [&] {
            e.select({fresh, branchStep, transitionAfter(e, branchStep)});
            return e.trigger(QStringLiteral("sfcDelete"));
        });
        e.select({e.stepId(QStringLiteral("Mix"))});
        f.run("parallel branch left", [&] { return e.trigger(QStringLiteral("sfcParLeft")); });
        // A step without IEC actions becomes a simplified step with an active and an exit action.
        quint64 plain = 0;
        for (const Element &element : e.document().elements)
            if (const auto *step = std::get_if<model::Step>(&element); step && !step->initialStep && !plain
                && stepActions(e.document(), step->localId).empty())
                plain = step->localId;
        QVERIFY(plain);
        StepProperties simplified = *stepProperties(e.document(), plain);
        simplified.options.simplified = true;
        simplified.options.activeAction = QStringLiteral("Plain_active");
        simplified.options.exitAction = QStringLiteral("Plain_exit");
        simplified.options.minTime = QStringLiteral("T#2s");
        f.run("simplified step", [&] { return e.edit(QStringLiteral("Change step"), [&](ChartDocument &d, const auto &) { return setStepProperties(d, plain, simplified); }); });
        f.run("entry action by its corner", [&] { return e.openStepAction(e.stepId(QStringLiteral("Drain")), QStringLiteral("entry")); });
        const quint64 afterFillA = transitionAfter(e, e.stepId(QStringLiteral("Fill_A")));
        f.run("condition in place", [&] {
            e.select({afterFillA});
            e.trigger(QStringLiteral("sfcCondition"));
            auto *line = e.findChild<QLineEdit *>(QStringLiteral("inPlaceEditor"));
            if (!line)
                return false;
            line->setText(QStringLiteral("L2 AND NOT L3"));
            QTest::keyClick(line, Qt::Key_Return);
            return true;
        });
        quint64 macro = 0;
        for (const Element &element : e.document().elements)
            if (std::holds_alternative<model::MacroStep>(element))
                macro = model::header(element).localId;
        QVERIFY(e.enterMacro(macro));
        e.select({model::header(e.document().elements.front()).localId});
        f.run("step inside the macro", [&] { return e.trigger(QStringLiteral("sfcStepAfter")); });
        // The new last step of the macro's chain ends in a transition-jump back to its first.
        for (const Element &element : e.document().elements)
            if (std::holds_alternative<model::Step>(element) && model::header(element).localId != model::header(e.document().elements.front()).localId)
                e.select({model::header(element).localId});
        f.run("transition-jump", [&] {
            const QString first = e.document().stepName(model::header(e.document().elements.front()).localId);
            return e.edit(QStringLiteral("Insert transition-jump"), [&](ChartDocument &d, const auto &s) { return insertTransitionJump(d, s, first); });
        });
        QVERIFY(e.leaveMacro());
        e.select({e.stepId(QStringLiteral("Fill_B")), transitionAfter(e, e.stepId(QStringLiteral("Fill_B")))});
        f.run("cut", [&] { return e.trigger(QStringLiteral("sfcCut")); });
        f.run("arrange", [&] { return e.arrangeChart(); });
    }

    void everyCommandUndoesAndRedoesExactly()
    {
        Fixture f;
        buildMixingTank(f);
        applyEveryCommand(f);
        // Undo everything, one gesture at a time, and compare with the state before it.
        for (int i = int(f.states.size()) - 1; i > 0; --i) {
            f.stack.undo();
            QVERIFY2(pouOf(f) == f.states[std::size_t(i) - 1], qPrintable(QString::number(i)));
        }
        for (std::size_t i = 1; i < f.states.size(); ++i) {
            f.stack.redo();
            QVERIFY2(pouOf(f) == f.states[i], qPrintable(QString::number(i)));
        }
    }

    void everyCommandSavesAValidFile()
    {
        Fixture f;
        f.validate = true;
        buildMixingTank(f);
        applyEveryCommand(f);
        QVERIFY(f.states.size() > 40);
    }

    void refusalsKeepTheChartValid()
    {
        Fixture f;
        buildMixingTank(f);
        SfcEditor &e = *f.editor;
        const auto before = elementsOf(f.model, f.ref);
        e.select({e.stepId(QStringLiteral("Mix"))});
        QVERIFY(!e.trigger(QStringLiteral("sfcAltRight"))); // needs a transition
        QVERIFY(e.lastMessage().contains(QStringLiteral("transition")));
        e.select({e.stepId(QStringLiteral("Init"))});
        QVERIFY(!e.trigger(QStringLiteral("sfcStepBefore")));
        QVERIFY(!e.trigger(QStringLiteral("sfcDelete")));
        QVERIFY(!e.edit(QStringLiteral("Insert jump"), [&](ChartDocument &d, const auto &s) { return insertJump(d, s, QStringLiteral("Nowhere")); }));
        QVERIFY(elementsOf(f.model, f.ref) == before);
    }

    void entryCornerCreatesAndOpensTheAction()
    {
        Fixture f;
        buildMixingTank(f);
        SfcEditor &e = *f.editor;
        QSignalSpy opened(&e, &SfcEditor::openPartRequested);
        const quint64 drain = e.stepId(QStringLiteral("Drain"));
        const int steps = f.stack.count();
        QVERIFY(e.openStepAction(drain, QStringLiteral("entry")));
        QCOMPARE(f.stack.count(), steps + 1); // one gesture: the action and the step's entry
        QCOMPARE(opened.count(), 1);
        QCOMPARE(opened.front().at(2).toString(), QStringLiteral("Drain_entry"));
        QVERIFY(f.model.findPouPart(f.ref.pou, BodyRef::Part::Action, QStringLiteral("Drain_entry")));
        QCOMPARE(stepProperties(e.document(), drain)->options.entryAction, QStringLiteral("Drain_entry"));
        f.stack.undo();
        QVERIFY(!f.model.findPouPart(f.ref.pou, BodyRef::Part::Action, QStringLiteral("Drain_entry")));
        QVERIFY(stepProperties(e.document(), drain)->options.entryAction.isEmpty());
    }

    void conditionIsEditedInPlace()
    {
        Fixture f;
        buildMixingTank(f);
        SfcEditor &e = *f.editor;
        e.show();
        const quint64 t = transitionAfter(e, e.stepId(QStringLiteral("Fill_A")));
        e.select({t});
        e.action(QStringLiteral("sfcCondition"))->trigger();
        auto *line = e.findChild<QLineEdit *>(QStringLiteral("inPlaceEditor"));
        QVERIFY(line);
        QCOMPARE(line->text(), QStringLiteral("L2"));
        line->setText(QStringLiteral("L2 AND NOT Fault"));
        QTest::keyClick(line, Qt::Key_Return);
        QCOMPARE(conditionOf(e, t), QStringLiteral("L2 AND NOT Fault"));
    }

    void arrowKeysWalkTheChart()
    {
        Fixture f;
        buildMixingTank(f);
        SfcEditor &e = *f.editor;
        e.select({e.stepId(QStringLiteral("Init"))});
        QTest::keyClick(e.view(), Qt::Key_Down);
        QCOMPARE(e.selection(), QList<quint64> {transitionAfter(e, e.stepId(QStringLiteral("Init")))});
        QTest::keyClick(e.view(), Qt::Key_Down);
        QCOMPARE(e.selection(), QList<quint64> {e.stepId(QStringLiteral("Fill_A"))});
        QTest::keyClick(e.view(), Qt::Key_Up);
        QTest::keyClick(e.view(), Qt::Key_Up);
        QCOMPARE(e.selection(), QList<quint64> {e.stepId(QStringLiteral("Init"))});
    }

    void macroStepOpensItsInside()
    {
        Fixture f;
        SfcEditor &e = *f.editor;
        f.run("new chart", [&] { return e.trigger(QStringLiteral("sfcNewChart")); });
        f.run("macro", [&] { return e.trigger(QStringLiteral("sfcMacro")); });
        const quint64 macro = e.selection().front();
        QVERIFY(e.enterMacro(macro));
        QCOMPARE(e.document().elements.size(), std::size_t(1));
        const quint64 inner = model::header(e.document().elements.front()).localId;
        e.select({inner});
        f.run("step inside the macro", [&] { return e.trigger(QStringLiteral("sfcStepAfter")); });
        QCOMPARE(e.document().elements.size(), std::size_t(3));
        QVERIFY(e.leaveMacro());
        QCOMPARE(e.selection(), QList<quint64> {macro});
        const auto innerCount = [&] {
            const ChartDocument doc = e.document();
            return (*std::get<model::MacroStep>(*doc.element(macro)).body)->elements()->size();
        };
        QCOMPARE(innerCount(), std::size_t(3));
        f.stack.undo();
        QCOMPARE(innerCount(), std::size_t(1));
    }

    // Item 7 of issue 13: tool bar, context menu and the macro level label follow the UI
    // language, also after several switches; a message of the old language goes.
    void followsTheUiLanguage()
    {
        Fixture f;
        SfcEditor &e = *f.editor;
        QVERIFY(e.trigger(QStringLiteral("sfcNewChart")));
        QVERIFY(e.trigger(QStringLiteral("sfcMacro")));
        QVERIFY(e.enterMacro(e.selection().front()));
        auto *label = e.findChild<QLabel *>(QStringLiteral("sfcLevelLabel"));
        auto *bar = e.findChild<QToolBar *>(QStringLiteral("diagramToolBar"));
        const auto buttonText = [&](const char *id) {
            auto *button = qobject_cast<QToolButton *>(bar->widgetForAction(e.action(QString::fromLatin1(id))));
            return button ? button->text() : QString();
        };
        const auto menuTexts = [&] {
            QStringList texts;
            for (QAction *action : e.contextMenuActions())
                if (!action->isSeparator())
                    texts << action->text();
            return texts;
        };
        const QStringList english = menuTexts();
        QVERIFY(english.contains(QStringLiteral("Step-Transition (after)")));
        const QString level = label->text();
        tests::BracketTranslator translator;
        for (int round = 0; round < 2; ++round) {
            QVERIFY(!e.trigger(QStringLiteral("sfcNewChart"))); // a refusal on the message line
            QVERIFY(!e.lastMessage().isEmpty());
            tests::switchLanguage(&translator, nullptr);
            QCOMPARE(e.lastMessage(), QString());
            QCOMPARE(e.action(QStringLiteral("sfcStepAfter"))->text(), QStringLiteral("[Step-Transition (after)]"));
            // The tool bar's short label, translated too.
            QCOMPARE(buttonText("sfcStepAfter"), QStringLiteral("[Step]"));
            QCOMPARE(buttonText("zoomIn"), QStringLiteral("[Zoom +]"));
            QStringList bracketed;
            for (const QString &text : english)
                bracketed << QLatin1Char('[') + text + QLatin1Char(']');
            QCOMPARE(menuTexts(), bracketed);
            QVERIFY2(label->text().startsWith(QStringLiteral("[Inside macro step")), qPrintable(label->text()));
            tests::switchLanguage(nullptr, &translator);
            QCOMPARE(menuTexts(), english);
            QCOMPARE(label->text(), level);
        }
    }

    void onlineShowsActiveStepsAndRefusesEdits()
    {
        Fixture f;
        buildMixingTank(f);
        SfcEditor &e = *f.editor;
        QCOMPARE(e.onlineInstance(), QStringLiteral("Tank"));
        interp::RuntimeSnapshot snapshot;
        interp::sfc::ChartState chart;
        chart.instance = QStringLiteral("Tank");
        chart.pou = QStringLiteral("Tank");
        for (const QString &name : {QStringLiteral("Init"), QStringLiteral("Fill_A"), QStringLiteral("Fill_B"),
                 QStringLiteral("Mix"), QStringLiteral("Drain")}) {
            const bool active = name == QLatin1String("Mix");
            chart.steps.push_back({name, e.stepId(name), active, active ? 3200000000 : 0});
        }
        chart.actions.push_back({QStringLiteral("M"), true});
        // Y1 still runs (as an action stored by one step runs after it): the row of Fill_A, whose
        // step is not active, is not coloured for it (issue 13 item 11).
        chart.actions.push_back({QStringLiteral("Y1"), true});
        chart.transitions.push_back({transitionAfter(e, e.stepId(QStringLiteral("Fill_B"))), true});
        snapshot.charts.push_back(chart);
        e.setOnlineSnapshot(&snapshot);
        auto *mix = e.scene()->itemFor(e.stepId(QStringLiteral("Mix")));
        QVERIFY(mix->isActive());
        QCOMPARE(mix->onlineText(), QStringLiteral("T#3s200ms"));
        QVERIFY(!e.scene()->itemFor(e.stepId(QStringLiteral("Init")))->isActive());
        QVERIFY(e.scene()->itemFor(transitionAfter(e, e.stepId(QStringLiteral("Fill_B"))))->isActive());
        const quint64 mixBlock = e.document().actionBlockOf(e.stepId(QStringLiteral("Mix")));
        QVERIFY(static_cast<ActionBlockItem *>(e.scene()->itemFor(mixBlock))->isActionActive(0));
        const quint64 fillBlock = e.document().actionBlockOf(e.stepId(QStringLiteral("Fill_A")));
        QVERIFY(!static_cast<ActionBlockItem *>(e.scene()->itemFor(fillBlock))->isActionActive(0));
        e.resize(760, 900);
        e.fitToWindow();
        QVERIFY(e.grab().save(shotDir() + QStringLiteral("/sfc_online.png")));
        // Editing is refused with a message while online.
        const int steps = f.stack.count();
        e.select({e.stepId(QStringLiteral("Mix"))});
        QVERIFY(!e.trigger(QStringLiteral("sfcDelete")));
        QVERIFY(e.lastMessage().contains(QStringLiteral("online")));
        QCOMPARE(f.stack.count(), steps);
        // Offline again: overlays gone, editable again.
        e.setOnlineSnapshot(nullptr);
        QVERIFY(!e.scene()->itemFor(e.stepId(QStringLiteral("Mix")))->isActive());
        QVERIFY(e.scene()->itemFor(e.stepId(QStringLiteral("Mix")))->onlineText().isEmpty());
        QVERIFY(e.trigger(QStringLiteral("sfcDelete")));
        QCOMPARE(f.stack.count(), steps + 1);
    }

    void importedChartStaysEditable()
    {
        // CODESYS writes no positions and numbers its elements from 0: shown in the editor's layout,
        // edited, undone to exactly what was read.
        const auto read = model::plcopen::readProjectFile(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/codesys35sp18_sfc_test.xml"));
        if (read.fileError)
            QSKIP("the PLCopen corpus of shared/ is not there");
        model::ProjectModel projectModel;
        projectModel.reset(read.project);
        QUndoStack stack;
        const BodyRef ref {projectModel.project().findPou(QStringLiteral("PLC_PRG"))->id};
        SfcEditor editor(projectModel, ref, &stack);
        const auto before = elementsOf(projectModel, ref);
        const quint64 step4 = editor.stepId(QStringLiteral("Step4"));
        QVERIFY(editor.scene()->itemFor(step4));
        QVERIFY(editor.scene()->itemFor(0)); // Init, localId 0
        editor.select({step4});
        QVERIFY2(editor.trigger(QStringLiteral("sfcParRight")), qPrintable(editor.lastMessage()));
        QCOMPARE(editor.document().chart.main.size(), std::size_t(5)); // Init, block, Step4 in a block, block, jump
        QVERIFY(editor.document().chart.loose.empty());
        stack.undo();
        QVERIFY(elementsOf(projectModel, ref) == before);
    }

    void picturesOfTheChart()
    {
        Fixture f;
        buildMixingTank(f);
        SfcEditor &e = *f.editor;
        // An entry action, a parallel branch and a true transition make the picture show them all.
        StepProperties drain = *stepProperties(e.document(), e.stepId(QStringLiteral("Drain")));
        drain.options.entryAction = QStringLiteral("OpenValve");
        drain.options.exitAction = QStringLiteral("CloseValve");
        QVERIFY(e.edit(QStringLiteral("Change step"), [&](ChartDocument &d, const auto &) { return setStepProperties(d, e.stepId(QStringLiteral("Drain")), drain); }));
        e.select({e.stepId(QStringLiteral("Mix"))});
        QVERIFY(e.trigger(QStringLiteral("sfcParRight")));
        QVERIFY(e.edit(QStringLiteral("Add action"), [&](ChartDocument &d, const auto &) { return addAction(d, e.selection().front(), actionAssociation(QStringLiteral("L"), QStringLiteral("Heater"), QStringLiteral("T#3s"))); }));
        e.resize(760, 900);
        e.fitToWindow();
        e.select({});
        QVERIFY(e.grab().save(shotDir() + QStringLiteral("/sfc_offline.png")));
        for (const char *suffix : {"svg", "png", "pdf"}) {
            const QString path = shotDir() + QStringLiteral("/sfc_chart.") + QLatin1String(suffix);
            QFile::remove(path);
            QCOMPARE(e.exportTo(path), QString());
            QVERIFY(QFileInfo(path).size() > 1000);
        }
        QFile svg(shotDir() + QStringLiteral("/sfc_chart.svg"));
        QVERIFY(svg.open(QIODevice::ReadOnly));
        const QByteArray text = svg.readAll();
        QVERIFY(text.contains("Fill_A"));
        QVERIFY(text.contains("NOT L3 AND SB2"));
        qInfo("pictures in %s", qPrintable(shotDir()));
    }
};

QTEST_MAIN(TestSfcEditor)
#include "tst_sfceditor.moc"
