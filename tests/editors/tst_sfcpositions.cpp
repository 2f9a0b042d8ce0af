// Edits keep the positions a chart has (Beremiz charts of the corpus, charts the user arranged):
// every editor command is applied at every step of the charts, and only what the command adds,
// the column below it and the branches right of it may move, in the directions the command
// needs; wires stay attached to their pins; undo restores the exact elements; saving keeps the
// positions. Charts without positions keep the automatic layout, and "Arrange Chart" lays any
// chart out in one undo step. Labels never run into the next branch.
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/sfc/sfceditor.h"
#include "editors/sfc/sfcgeometry.h"
#include "editors/sfc/sfcitems.h"
#include "editors/sfc/sfclayout.h"
#include "model/body.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"
#include "model/undo/bodyelementscommand.h"

#include <QDir>
#include <QTest>
#include <QUndoStack>

#include <map>

using namespace iec;
using namespace iec::editors::sfc;
using model::BodyRef;
using model::Element;

namespace {

const QString kCorpus = QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/");

// One POU's chart open in an editor, as the app opens it.
struct Open {
    model::ProjectModel model;
    QUndoStack stack;
    BodyRef ref;
    std::unique_ptr<SfcEditor> editor;

    [[nodiscard]] std::vector<Element> elements() const { return *model.body(ref)->elements(); }
};

std::unique_ptr<Open> open(const QString &path, const QString &pou)
{
    const auto read = model::plcopen::readProjectFile(path);
    if (read.fileError)
        return nullptr;
    auto opened = std::make_unique<Open>();
    opened->model.reset(read.project);
    const model::Pou *found = opened->model.project().findPou(pou);
    if (!found)
        return nullptr;
    opened->ref = BodyRef {found->id};
    opened->editor = std::make_unique<SfcEditor>(opened->model, opened->ref, &opened->stack);
    opened->editor->resize(1000, 800);
    return opened;
}

std::map<quint64, const Element *> byId(const std::vector<Element> &elements)
{
    std::map<quint64, const Element *> map;
    for (const Element &e : elements)
        map.emplace(model::header(e).localId, &e);
    return map;
}

quint64 transitionAfter(const std::vector<Element> &elements, quint64 stepId)
{
    for (const Element &e : elements)
        if (const auto *t = std::get_if<model::Transition>(&e); t && t->connectionPointIn)
            for (const auto &c : t->connectionPointIn->connections)
                if (c.refLocalId == stepId)
                    return t->localId;
    return 0;
}

// The transition that follows a step: the one wired to it, or when the step opens an alternative
// branch, the rightmost branch's first transition (the main column of the traffic light).
quint64 nextTransition(const std::vector<Element> &elements, quint64 stepId)
{
    if (const quint64 direct = transitionAfter(elements, stepId))
        return direct;
    for (const Element &e : elements) {
        const auto *d = std::get_if<model::SelectionDivergence>(&e);
        if (!d || !d->connectionPointIn || d->connectionPointIn->connections.empty()
            || d->connectionPointIn->connections.front().refLocalId != stepId)
            continue;
        quint64 best = 0;
        double bestX = -1e9;
        for (const Element &t : elements)
            if (const quint64 id = transitionAfter({t}, d->localId); id && model::header(t).position.x > bestX) {
                best = id;
                bestX = model::header(t).position.x;
            }
        return best;
    }
    return 0;
}

bool isChainOrBlock(const Element &e)
{
    return isBar(e) || std::holds_alternative<model::Step>(e) || std::holds_alternative<model::MacroStep>(e)
        || std::holds_alternative<model::Transition>(e) || std::holds_alternative<model::JumpStep>(e)
        || std::holds_alternative<model::ActionBlock>(e);
}

// The point of an element's pin nearest to `near` (a bar's pins lie anywhere along it).
QPointF pinOf(const Element &e, QPointF near, bool input)
{
    if (!isBar(e))
        return input ? inputPoint(e) : outputPoint(e);
    const QRectF bar = elementRect(e);
    return {std::clamp(near.x(), bar.left(), bar.right()), input ? bar.top() : bar.bottom()};
}

// How far each structural wire's ends are from the pins they attach to, by (target, source).
using WireEnds = std::map<std::pair<quint64, quint64>, std::pair<QPointF, QPointF>>;

WireEnds wireEnds(const std::vector<Element> &elements)
{
    const auto ids = byId(elements);
    WireEnds ends;
    for (const Element &e : elements) {
        if (!isChainOrBlock(e) || std::holds_alternative<model::ActionBlock>(e))
            continue;
        std::vector<const model::ConnectionPointIn *> points = model::inputPoints(e);
        if (const auto *t = std::get_if<model::Transition>(&e))
            points = t->connectionPointIn ? std::vector<const model::ConnectionPointIn *> {&*t->connectionPointIn}
                                          : std::vector<const model::ConnectionPointIn *> {};
        for (const model::ConnectionPointIn *point : points) {
            for (const model::Connection &c : point->connections) {
                const auto source = ids.find(c.refLocalId);
                if (source == ids.end() || c.waypoints.size() < 2)
                    continue;
                const QPointF first(c.waypoints.front().x, c.waypoints.front().y);
                const QPointF last(c.waypoints.back().x, c.waypoints.back().y);
                ends[{model::header(e).localId, c.refLocalId}]
                    = {first - pinOf(e, first, true), last - pinOf(*source->second, last, false)};
            }
        }
    }
    return ends;
}

bool near(QPointF a, QPointF b)
{
    return std::abs(a.x() - b.x()) < 1e-6 && std::abs(a.y() - b.y()) < 1e-6;
}

// Every wire attaches where it did before (a wire kept with its ends' offsets), or exactly at
// its pins (a wire routed again). Returns the first wire that does not.
QString detachedWire(const std::vector<Element> &before, const std::vector<Element> &after)
{
    const WireEnds was = wireEnds(before);
    for (const auto &[key, offsets] : wireEnds(after)) {
        const bool atPins = near(offsets.first, {}) && near(offsets.second, {});
        const auto old = was.find(key);
        const bool asBefore = old != was.end() && near(old->second.first, offsets.first) && near(old->second.second, offsets.second);
        if (!atPins && !asBefore) {
            auto show = [](QPointF p) { return QStringLiteral("(%1,%2)").arg(p.x()).arg(p.y()); };
            return QStringLiteral("wire %1 <- %2: ends off their pins by %3 %4, before %5")
                .arg(key.first)
                .arg(key.second)
                .arg(show(offsets.first), show(offsets.second),
                    old == was.end() ? QStringLiteral("none") : show(old->second.first) + show(old->second.second));
        }
    }
    return {};
}

QString signatureOf(const ChartDocument &doc, const Sequence &seq)
{
    QStringList parts;
    for (const Node &node : seq) {
        switch (node.kind) {
        case NodeKind::Step:
        case NodeKind::MacroStep:
            parts << doc.stepName(node.localId);
            break;
        case NodeKind::Transition:
            parts << QStringLiteral("t");
            break;
        case NodeKind::Jump:
            parts << QStringLiteral("->") + (node.wired ? doc.stepName(node.wiredTarget)
                                                         : std::get<model::JumpStep>(*doc.element(node.localId)).targetName);
            break;
        case NodeKind::Selection:
        case NodeKind::Parallel: {
            QStringList branches;
            for (const Sequence &branch : node.branches)
                branches << signatureOf(doc, branch);
            const QString separator = node.kind == NodeKind::Selection ? QStringLiteral(" | ") : QStringLiteral(" || ");
            parts << QStringLiteral("[") + branches.join(separator) + QStringLiteral("]");
            break;
        }
        }
    }
    return parts.join(QLatin1Char(' '));
}

enum class Direction { Grow, Shrink, Change };

struct Command {
    const char *name;
    Direction direction;
};

// The editor commands, applied at a step (or the transition after it), as a user applies them.
const Command kCommands[] = {
    {"after", Direction::Grow}, {"before", Direction::Grow}, {"after-transition", Direction::Grow},
    {"alternative-right", Direction::Grow}, {"alternative-left", Direction::Grow}, {"parallel-right", Direction::Grow},
    {"parallel-left", Direction::Grow}, {"macro", Direction::Grow}, {"paste", Direction::Grow},
    {"delete", Direction::Shrink}, {"delete-branch", Direction::Shrink}, {"action", Direction::Change},
    {"rename", Direction::Change}, {"condition", Direction::Change}};

// The network wired into a transition's condition (variables, blocks, contacts), which moves with it.
std::map<quint64, quint64> conditionNetworks(const std::vector<Element> &elements)
{
    const auto ids = byId(elements);
    std::map<quint64, quint64> owner; // element → the transition it feeds
    for (const Element &e : elements) {
        const auto *t = std::get_if<model::Transition>(&e);
        const auto *wire = t && t->condition ? std::get_if<model::ConnectionPointIn>(&t->condition->kind) : nullptr;
        if (!wire)
            continue;
        std::vector<quint64> pending;
        for (const model::Connection &c : wire->connections)
            pending.push_back(c.refLocalId);
        while (!pending.empty()) {
            const quint64 id = pending.back();
            pending.pop_back();
            const auto found = ids.find(id);
            if (found == ids.end() || owner.contains(id) || isChainOrBlock(*found->second))
                continue;
            owner[id] = t->localId;
            for (const model::ConnectionPointIn *point : model::inputPoints(*found->second))
                for (const model::Connection &c : point->connections)
                    pending.push_back(c.refLocalId);
        }
    }
    return owner;
}

// Runs a command; nullopt when it does not apply to that step (no branch to delete).
std::optional<bool> apply(SfcEditor &e, const QString &command, quint64 step, quint64 transition)
{
    if (command == QLatin1String("after") || command == QLatin1String("before")) {
        e.select({step});
        return command == QLatin1String("after") ? e.trigger(QStringLiteral("sfcStepAfter")) : e.trigger(QStringLiteral("sfcStepBefore"));
    }
    if (command == QLatin1String("after-transition")) {
        e.select({transition});
        return e.trigger(QStringLiteral("sfcStepAfter"));
    }
    if (command.startsWith(QLatin1String("alternative"))) {
        e.select({transition});
        return e.trigger(command.endsWith(QLatin1String("right")) ? QStringLiteral("sfcAltRight") : QStringLiteral("sfcAltLeft"));
    }
    if (command.startsWith(QLatin1String("parallel"))) {
        e.select({step});
        return e.trigger(command.endsWith(QLatin1String("right")) ? QStringLiteral("sfcParRight") : QStringLiteral("sfcParLeft"));
    }
    if (command == QLatin1String("macro")) {
        e.select({transition});
        return e.trigger(QStringLiteral("sfcMacro"));
    }
    if (command == QLatin1String("paste")) {
        e.select({step, transition});
        if (!e.trigger(QStringLiteral("sfcCopy")))
            return false;
        e.select({transition});
        return e.trigger(QStringLiteral("sfcPaste"));
    }
    if (command == QLatin1String("delete")) {
        e.select({step, transition});
        return e.trigger(QStringLiteral("sfcDelete"));
    }
    if (command == QLatin1String("delete-branch")) {
        // The whole branch the step is in: its range from the divergence's first element on.
        ChartDocument doc = e.document();
        const std::optional<NodePlace> place = findNode(doc.chart, step);
        if (!place || !place->parent)
            return std::nullopt;
        QList<quint64> all;
        for (const Node &node : *place->sequence)
            for (quint64 id : elementsOf(doc, node))
                all << id;
        e.select(all);
        return e.trigger(QStringLiteral("sfcDelete"));
    }
    if (command == QLatin1String("action"))
        return e.edit(QStringLiteral("Add action"), [&](ChartDocument &d, const auto &) { return addAction(d, step, actionAssociation(QStringLiteral("N"), QStringLiteral("HornWithALongName"))); });
    if (command == QLatin1String("rename")) {
        StepProperties properties = *stepProperties(e.document(), step);
        properties.name += QStringLiteral("_AndALongerName");
        return e.edit(QStringLiteral("Change step"), [&](ChartDocument &d, const auto &) { return setStepProperties(d, step, properties); });
    }
    if (command == QLatin1String("condition"))
        return e.edit(QStringLiteral("Change condition"), [&](ChartDocument &d, const auto &) { return setInlineCondition(d, transition, QStringLiteral("LevelHigh AND NOT StopRequested AND Timer.Q")); });
    return false;
}

QString shotDir()
{
    const QString dir = qEnvironmentVariable("IEC_SHOT_DIR", QDir::tempPath() + QStringLiteral("/iec-sfc-shots"));
    QDir().mkpath(dir);
    return dir;
}

void shoot(SfcEditor &editor, const QString &name)
{
    if (qEnvironmentVariableIsEmpty("IEC_SHOT_DIR"))
        return;
    editor.exportTo(shotDir() + QLatin1Char('/') + name + QStringLiteral(".png"));
}

} // namespace

class TestSfcPositions : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void everyCommandKeepsTheOtherPositions_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("pou");
        QTest::addColumn<QString>("step");
        QTest::addColumn<QString>("command");
        QTest::addColumn<int>("direction");
        const struct {
            const char *file;
            const char *pou;
            QStringList steps;
        } charts[] = {
            {"beremiz_first_steps.xml", "CounterSFC", {"Start", "Count", "ResetCounter"}},
            {"beremiz_svghmi_traffic_light.xml", "traffic_light_sequence",
                {"Standstill", "ORANGE", "RED", "PEDESTRIAN_GREEN", "PEDESTRIAN_RED", "GREEN"}},
        };
        for (const auto &chart : charts)
            for (const QString &step : chart.steps)
                for (const Command &command : kCommands)
                    QTest::addRow("%s %s %s", chart.pou, qPrintable(step), command.name)
                        << QString::fromLatin1(chart.file) << QString::fromLatin1(chart.pou) << step
                        << QString::fromLatin1(command.name) << int(command.direction);
    }

    void everyCommandKeepsTheOtherPositions()
    {
        QFETCH(QString, file);
        QFETCH(QString, pou);
        QFETCH(QString, step);
        QFETCH(QString, command);
        QFETCH(int, direction);
        std::unique_ptr<Open> o = open(kCorpus + file, pou);
        if (!o)
            QSKIP("the PLCopen corpus of shared/ is not there");
        QVERIFY(!o->model.body(o->ref)->layoutGenerated);
        SfcEditor &e = *o->editor;
        const std::vector<Element> before = o->elements();
        const quint64 stepId = e.stepId(step);
        QVERIFY(stepId);
        const quint64 transitionId = nextTransition(before, stepId);
        // Where the edit happens: nothing above it moves down, nothing moves left.
        double editTop = std::min(elementRect(*byId(before).at(stepId)).top(),
            transitionId ? elementRect(*byId(before).at(transitionId)).top() : 1e9);
        if (command == QLatin1String("delete-branch")) { // the block it leaves may dissolve
            ChartDocument doc = e.document();
            if (const std::optional<NodePlace> place = findNode(doc.chart, stepId); place && place->parent)
                editTop = elementRect(*byId(before).at(place->parent->localId)).top();
        }
        const std::optional<bool> applied = apply(e, command, stepId, transitionId);
        if (!applied)
            return;
        if (!*applied) {
            QVERIFY2(!e.lastMessage().isEmpty(), "a refused command says why");
            QVERIFY(o->elements() == before);
            return;
        }
        QCOMPARE(o->stack.count(), 1);
        const std::vector<Element> after = o->elements();
        const auto was = byId(before);
        const auto now = byId(after);
        const std::map<quint64, quint64> networks = conditionNetworks(after);
        const auto moved = [&](quint64 id) {
            const model::Position from = model::header(*was.at(id)).position;
            const model::Position to = model::header(*now.at(id)).position;
            return QPointF(to.x - from.x, to.y - from.y);
        };
        for (const auto &[id, element] : now) {
            const auto old = was.find(id);
            if (old == was.end())
                continue;
            const model::Position from = model::header(*old->second).position;
            const model::Position to = model::header(*element).position;
            if (from == to)
                continue;
            const double dx = to.x - from.x;
            const double dy = to.y - from.y;
            const QString where = QStringLiteral("element %1 moved by (%2, %3)").arg(id).arg(dx).arg(dy);
            if (!isChainOrBlock(*element)) {
                // Only a condition's network moves, together with its transition.
                const auto network = networks.find(id);
                QVERIFY2(network != networks.end(), qPrintable(where + QStringLiteral(": it is not part of the chart")));
                QCOMPARE(moved(id), moved(network->second));
                continue;
            }
            if (command == QLatin1String("rename") && id == stepId) { // grows around its axis (its branch may move right)
                QVERIFY(elementRect(*element).center().x() >= elementRect(*old->second).center().x());
                QCOMPARE(dy, 0.0);
                continue;
            }
            if (direction == int(Direction::Shrink)) {
                // A deletion closes its gap below it (a dissolved block also moves its branch back
                // onto the chain's axis); nothing above it moves.
                QVERIFY2(from.y >= editTop - 0.5, qPrintable(where));
                QVERIFY2(dy <= 0.5, qPrintable(where));
            } else {
                QVERIFY2(dx >= -0.5 && dy >= -0.5, qPrintable(where));
                QVERIFY2(dy < 0.5 || from.y >= editTop - 0.5, qPrintable(where + QStringLiteral(" though it is above the edit")));
            }
        }
        // Wires stay attached; the chart reads back as the structure the editor made.
        QCOMPARE(detachedWire(before, after), QString());
        const ChartDocument reread = readChart(after);
        QVERIFY(!reread.chart.main.empty());
        QCOMPARE(signatureOf(reread, reread.chart.main), signatureOf(e.document(), e.document().chart.main));
        // Nothing new overlaps: frames of steps, transitions, bars, jumps and action blocks.
        std::vector<std::pair<quint64, QRectF>> framesBefore;
        std::vector<std::pair<quint64, QRectF>> framesAfter;
        for (const Element &element : before)
            if (isChainOrBlock(element))
                framesBefore.emplace_back(model::header(element).localId, elementRect(element));
        for (const Element &element : after)
            if (isChainOrBlock(element))
                framesAfter.emplace_back(model::header(element).localId, elementRect(element));
        auto overlapped = [&](quint64 a, quint64 b) {
            QRectF ra;
            QRectF rb;
            for (const auto &[id, rect] : framesBefore) {
                if (id == a)
                    ra = rect;
                if (id == b)
                    rb = rect;
            }
            return !ra.isNull() && !rb.isNull() && ra.intersects(rb);
        };
        for (std::size_t i = 0; i < framesAfter.size(); ++i)
            for (std::size_t j = i + 1; j < framesAfter.size(); ++j)
                if (framesAfter[i].second.intersects(framesAfter[j].second))
                    QVERIFY2(overlapped(framesAfter[i].first, framesAfter[j].first),
                        qPrintable(QStringLiteral("%1 / %2 overlap").arg(framesAfter[i].first).arg(framesAfter[j].first)));
        // Undo restores the exact elements, redo the edited ones; saving keeps the positions.
        o->stack.undo();
        QVERIFY(o->elements() == before);
        o->stack.redo();
        QVERIFY(o->elements() == after);
        const auto reread2 = model::plcopen::readProject(model::plcopen::writeProject(o->model.project()));
        QVERIFY(reread2.ok);
        QVERIFY(*reread2.project.findPou(pou)->body()->elements() == after);
        shoot(e, QStringLiteral("positions_%1_%2_%3").arg(pou, step, command));
    }

    void insertBelowShiftsOnlyItsColumn()
    {
        // CounterSFC: Start, then [Reset -> ResetCounter | NOT Reset -> Count], then a jump to Start.
        std::unique_ptr<Open> o = open(kCorpus + QStringLiteral("beremiz_first_steps.xml"), QStringLiteral("CounterSFC"));
        if (!o)
            QSKIP("the PLCopen corpus of shared/ is not there");
        SfcEditor &e = *o->editor;
        const std::vector<Element> before = o->elements();
        const auto was = byId(before);
        const quint64 count = e.stepId(QStringLiteral("Count"));
        QCOMPARE(count, quint64(7));
        shoot(e, QStringLiteral("counter_before"));
        e.select({count});
        QVERIFY(e.trigger(QStringLiteral("sfcStepAfter")));
        shoot(e, QStringLiteral("counter_after_insert"));
        const std::vector<Element> after = o->elements();
        const auto now = byId(after);
        // The other branch, the step above and the element edited keep their exact positions.
        for (quint64 id : {1, 2, 3, 4, 5, 6, 14, 7, 8})
            QVERIFY2(model::header(*now.at(id)).position == model::header(*was.at(id)).position, qPrintable(QString::number(id)));
        // The new transition and step hang below Count, on its axis.
        const QRectF countFrame = elementRect(*now.at(7));
        const quint64 fresh = transitionAfter(after, 7);
        QVERIFY(!was.contains(fresh));
        QCOMPARE(inputPoint(*now.at(fresh)).x(), outputPoint(*now.at(7)).x());
        QVERIFY(elementRect(*now.at(fresh)).top() >= countFrame.bottom() + kGap - 1e-9);
        // Count's old transition, the convergence and the jump below it moved straight down.
        const auto dy = [&](quint64 id) { return model::header(*now.at(id)).position.y - model::header(*was.at(id)).position.y; };
        const auto dx = [&](quint64 id) { return model::header(*now.at(id)).position.x - model::header(*was.at(id)).position.x; };
        QVERIFY(dy(13) > 0);
        QVERIFY(dy(10) > 0);
        QCOMPARE(dy(12), dy(10));
        for (quint64 id : {13, 10, 12})
            QCOMPARE(dx(id), 0.0);
        const quint64 freshStep = *e.document().stepNamed(QStringLiteral("Step1"));
        QVERIFY(elementRect(*now.at(13)).top() >= elementRect(*now.at(freshStep)).bottom() + kGap - 1e-9);
    }

    void newBranchGoesRightOfTheWidestDrawing()
    {
        std::unique_ptr<Open> o = open(kCorpus + QStringLiteral("beremiz_first_steps.xml"), QStringLiteral("CounterSFC"));
        if (!o)
            QSKIP("the PLCopen corpus of shared/ is not there");
        SfcEditor &e = *o->editor;
        const std::vector<Element> before = o->elements();
        // A parallel branch beside Count: right of Count's action block, pushing the
        // ResetCounter branch right as far as needed.
        const quint64 count = e.stepId(QStringLiteral("Count"));
        e.select({count});
        QVERIFY(e.trigger(QStringLiteral("sfcParRight")));
        shoot(e, QStringLiteral("counter_parallel"));
        const std::vector<Element> after = o->elements();
        const auto now = byId(after);
        const auto was = byId(before);
        const quint64 fresh = e.selection().front();
        const QRectF countBlock = elementRect(*now.at(8));
        QVERIFY(elementRect(*now.at(fresh)).left() >= countBlock.right() + kBranchGap - 1e-9);
        QCOMPARE(elementRect(*now.at(fresh)).top(), elementRect(*now.at(count)).top());
        const double pushed = model::header(*now.at(5)).position.x - model::header(*was.at(5)).position.x;
        QVERIFY(pushed > 0);
        for (quint64 id : {3, 5, 6, 14}) // the whole ResetCounter branch moved right together
            QCOMPARE(model::header(*now.at(id)).position.x - model::header(*was.at(id)).position.x, pushed);
        QCOMPARE(model::header(*now.at(1)).position, model::header(*was.at(1)).position);
        // The outer divergence now reaches the pushed branch.
        QVERIFY(elementRect(*now.at(2)).right() >= inputPoint(*now.at(3)).x() - 1e-9);
        QCOMPARE(detachedWire(before, after), QString());
    }

    void deleteClosesTheGapInItsColumnOnly()
    {
        std::unique_ptr<Open> o = open(kCorpus + QStringLiteral("beremiz_svghmi_traffic_light.xml"), QStringLiteral("traffic_light_sequence"));
        if (!o)
            QSKIP("the PLCopen corpus of shared/ is not there");
        SfcEditor &e = *o->editor;
        const std::vector<Element> before = o->elements();
        const auto was = byId(before);
        // Standstill, ORANGE, then [-> Standstill | t RED [...]]: delete the transition and RED of
        // the second branch; the block below RED takes their place.
        const quint64 red = e.stepId(QStringLiteral("RED"));
        QCOMPARE(red, quint64(10));
        shoot(e, QStringLiteral("traffic_before"));
        e.select({6, red});
        QVERIFY2(e.trigger(QStringLiteral("sfcDelete")), qPrintable(e.lastMessage()));
        shoot(e, QStringLiteral("traffic_after_delete"));
        const std::vector<Element> after = o->elements();
        const auto now = byId(after);
        QCOMPARE(elementRect(*now.at(7)).top(), elementRect(*was.at(6)).top());
        // Above the deletion and in the other branch nothing moved.
        QCOMPARE(model::header(*now.at(16)).position, model::header(*was.at(16)).position);
        QCOMPARE(model::header(*now.at(17)).position, model::header(*was.at(17)).position);
        for (const auto &[id, element] : was) {
            if (!now.contains(id))
                continue;
            if (elementRect(*element).top() < elementRect(*was.at(6)).top())
                QVERIFY2(model::header(*now.at(id)).position == model::header(*element).position, qPrintable(QString::number(id)));
        }
        // What followed moved up into the gap, by the same amount.
        double lift = 0;
        for (const auto &[id, element] : now) {
            if (!was.contains(id) || model::header(*element).position == model::header(*was.at(id)).position)
                continue;
            const double dy = model::header(*element).position.y - model::header(*was.at(id)).position.y;
            QVERIFY(dy < 0);
            if (lift == 0)
                lift = dy;
            QCOMPARE(dy, lift);
        }
        QVERIFY(lift < 0);
        QCOMPARE(detachedWire(before, after), QString());
    }

    void userArrangedPositionsSurviveEdits()
    {
        // A chart made in the editor, one step dragged aside by the user: editing elsewhere keeps it there.
        model::Project project;
        model::Pou pou;
        pou.name = QStringLiteral("Main");
        pou.kind = model::PouKind::Program;
        pou.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::SFC));
        project.types.pous.push_back(pou);
        model::ProjectModel projectModel;
        projectModel.reset(project);
        QUndoStack stack;
        const BodyRef ref {projectModel.project().types.pous.front().id};
        SfcEditor e(projectModel, ref, &stack);
        QVERIFY(e.trigger(QStringLiteral("sfcNewChart")));
        e.select({e.stepId(QStringLiteral("Init"))});
        QVERIFY(e.trigger(QStringLiteral("sfcStepAfter")));
        QVERIFY(e.trigger(QStringLiteral("sfcStepAfter")));
        std::vector<Element> arranged = *projectModel.body(ref)->elements();
        const quint64 step1 = e.stepId(QStringLiteral("Step1"));
        for (Element &element : arranged)
            if (model::header(element).localId == step1)
                model::header(element).position.x += 200;
        stack.push(new model::SetBodyElementsCommand(projectModel, ref, arranged, QStringLiteral("drag")));
        e.select({e.stepId(QStringLiteral("Step2"))});
        QVERIFY(e.trigger(QStringLiteral("sfcStepAfter")));
        const std::vector<Element> edited = *projectModel.body(ref)->elements();
        const auto now = byId(edited);
        QCOMPARE(model::header(*now.at(step1)).position, model::header(*byId(arranged).at(step1)).position);
        // Arrange Chart puts it back in the automatic layout, as one undo step.
        const int steps = stack.count();
        QVERIFY(e.arrangeChart());
        QCOMPARE(stack.count(), steps + 1);
        ChartDocument expected = readChart(edited);
        layoutChart(expected);
        QVERIFY(*projectModel.body(ref)->elements() == expected.elements);
        QVERIFY2(model::header(*byId(expected.elements).at(step1)).position.x < model::header(*now.at(step1)).position.x,
            qPrintable(QStringLiteral("%1 %2").arg(model::header(*byId(expected.elements).at(step1)).position.x).arg(model::header(*now.at(step1)).position.x)));
        stack.undo();
        QVERIFY(*projectModel.body(ref)->elements() == edited);
    }

    void unplacedChartsKeepTheAutomaticLayout()
    {
        std::unique_ptr<Open> o = open(kCorpus + QStringLiteral("codesys35sp18_sfc_test.xml"), QStringLiteral("PLC_PRG"));
        if (!o)
            QSKIP("the PLCopen corpus of shared/ is not there");
        QVERIFY(o->model.body(o->ref)->layoutGenerated);
        SfcEditor &e = *o->editor;
        e.select({e.stepId(QStringLiteral("Step4"))});
        QVERIFY(e.trigger(QStringLiteral("sfcStepAfter")));
        ChartDocument expected = readChart(o->elements());
        layoutChart(expected);
        QVERIFY(o->elements() == expected.elements);
    }

    void labelsStayOutOfTheNextBranch()
    {
        // The mixing tank's positions leave its long condition less room than it needs: it is
        // cut with "…" where the next branch begins (the tooltip has it whole).
        std::unique_ptr<Open> o = open(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/mixing_tank.xml"), QStringLiteral("Main"));
        QVERIFY(o);
        SfcEditor &e = *o->editor;
        auto *cut = static_cast<SfcItem *>(e.scene()->itemFor(16));
        QVERIFY(cut);
        QVERIFY(cut->labelRoom() >= 0);
        QVERIFY(cut->shownLabel().endsWith(QStringLiteral("…")));
        QVERIFY(cut->toolTip().contains(QStringLiteral("NOT L3 AND StopRequested")));
        QVERIFY(!cut->boundingRect().intersects(static_cast<SfcItem *>(e.scene()->itemFor(17))->frame()));
        shoot(e, QStringLiteral("mixing_tank_file"));
        // Arranged by the editor, branches leave room for their labels: nothing is cut.
        QVERIFY(e.arrangeChart());
        shoot(e, QStringLiteral("mixing_tank_arranged"));
        for (editors::DiagramItem *item : e.scene()->diagramItems()) {
            auto *sfcItem = static_cast<SfcItem *>(item);
            const QRectF label = labelRect(sfcItem->element());
            if (label.isEmpty())
                continue;
            QVERIFY2(sfcItem->labelRoom() < 0 || sfcItem->labelRoom() >= label.width(), qPrintable(sfcItem->shownLabel()));
            for (editors::DiagramItem *other : e.scene()->diagramItems())
                if (other != item)
                    QVERIFY(!label.intersects(static_cast<SfcItem *>(other)->frame()));
        }
    }

    void longConditionWidensItsBranch()
    {
        std::unique_ptr<Open> o = open(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/mixing_tank.xml"), QStringLiteral("Main"));
        QVERIFY(o);
        SfcEditor &e = *o->editor;
        // Editing the left branch's condition pushes the right branch out of its way.
        QVERIFY(e.edit(QStringLiteral("Change condition"), [&](ChartDocument &d, const auto &) { return setInlineCondition(d, 16, QStringLiteral("NOT L3 AND StopRequested AND NOT Fault AND Ready")); }));
        auto *left = static_cast<SfcItem *>(e.scene()->itemFor(16));
        QCOMPARE(left->shownLabel(), QStringLiteral("NOT L3 AND StopRequested AND NOT Fault AND Ready"));
        QVERIFY(!labelRect(left->element()).intersects(static_cast<SfcItem *>(e.scene()->itemFor(17))->frame()));
        shoot(e, QStringLiteral("mixing_tank_long_condition"));
    }

    void textWidthsFollowTheFont()
    {
        QCOMPARE(textWidth(QString()), 0.0);
        QCOMPARE(textWidth(QStringLiteral("i")), 4.0);          // 3.33 px, rounded up
        QCOMPARE(textWidth(QStringLiteral("WWW")), 36.0);       // 3 × 11.87
        QVERIFY(textWidth(QStringLiteral("MMMM")) > textWidth(QStringLiteral("iiii")) * 2);
    }

    void labelRoomIsTheGapToTheNextDrawing_data()
    {
        QTest::addColumn<QRectF>("label");
        QTest::addColumn<QList<QRectF>>("obstacles");
        QTest::addColumn<double>("room");
        const QRectF label(100, 50, 200, 18);
        QTest::newRow("nothing") << label << QList<QRectF> {} << -1.0;
        QTest::newRow("frame to the right") << label << QList<QRectF> {{250, 55, 20, 4}} << 146.0;
        QTest::newRow("above the row") << label << QList<QRectF> {{150, 0, 20, 40}} << -1.0;
        QTest::newRow("left of the label") << label << QList<QRectF> {{20, 50, 60, 30}} << -1.0;
        QTest::newRow("vertical wire") << label << QList<QRectF> {{180, 0, 0, 200}, {250, 55, 20, 4}} << 76.0;
        QTest::newRow("across the start") << label << QList<QRectF> {{90, 58, 50, 0}} << 0.0;
    }

    void labelRoomIsTheGapToTheNextDrawing()
    {
        QFETCH(QRectF, label);
        QFETCH(QList<QRectF>, obstacles);
        QFETCH(double, room);
        QCOMPARE(labelRoom(label, obstacles), room);
    }

    void fitToWindowZoomsSmallChartsIn()
    {
        model::Project project;
        model::Pou pou;
        pou.name = QStringLiteral("Main");
        pou.kind = model::PouKind::Program;
        pou.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::SFC));
        project.types.pous.push_back(pou);
        model::ProjectModel projectModel;
        projectModel.reset(project);
        QUndoStack stack;
        SfcEditor e(projectModel, BodyRef {projectModel.project().types.pous.front().id}, &stack);
        QVERIFY(e.trigger(QStringLiteral("sfcNewChart")));
        for (int i = 0; i < 5; ++i) // a column about 450 pixels tall
            QVERIFY(e.trigger(QStringLiteral("sfcStepAfter")));
        // Before the editor is shown (a tab opened in the background, a picture taken offscreen)
        // it fits the size it has, not the view's default size.
        e.resize(1200, 1600);
        e.fitToWindow();
        const QRectF chart = e.scene()->itemsBoundingRect();
        const QRect inside = e.view()->contentsRect();
        QVERIFY2(inside.height() > 1400, qPrintable(QString::number(inside.height())));
        const double expected = std::min(4.0, std::min(inside.width() / (chart.width() + 20), inside.height() / (chart.height() + 20)));
        QVERIFY2(e.view()->zoom() > 2.5, qPrintable(QString::number(e.view()->zoom())));
        QCOMPARE(e.view()->zoom(), expected);
        e.view()->resetZoom();
        e.resize(900, 700);
        e.show();
        QVERIFY(QTest::qWaitForWindowExposed(&e));
        e.fitToWindow();
        QVERIFY2(e.view()->zoom() > 1.0, qPrintable(QString::number(e.view()->zoom())));
        QVERIFY(e.view()->zoom() <= 4.0);
        // The whole chart is in the window.
        const QRectF drawing = e.scene()->itemsBoundingRect();
        const QRect shown = e.view()->mapFromScene(drawing).boundingRect();
        QVERIFY(e.view()->viewport()->rect().contains(shown));
        // Any chart stops at 400 %.
        e.resize(3000, 3000);
        e.fitToWindow();
        QCOMPARE(e.view()->zoom(), 4.0);
    }
};

QTEST_MAIN(TestSfcPositions)
#include "tst_sfcpositions.moc"
