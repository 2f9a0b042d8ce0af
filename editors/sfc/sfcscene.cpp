#include "editors/sfc/sfcscene.h"

#include "editors/common/blockitems.h"

#include "editors/sfc/sfcgeometry.h"
#include "editors/sfc/sfcitems.h"
#include "editors/sfc/sfclayout.h"
#include "model/body.h"
#include "model/projectmodel.h"

#include <QGraphicsPathItem>
#include <QPen>

#include <unordered_map>
#include <unordered_set>

namespace iec::editors::sfc {

using namespace model;

const std::vector<Element> *levelElements(const std::vector<Element> &top, const std::vector<quint64> &path)
{
    const std::vector<Element> *level = &top;
    for (quint64 id : path) {
        const auto it = std::ranges::find_if(*level, [&](const Element &e) { return header(e).localId == id; });
        const auto *macro = it == level->end() ? nullptr : std::get_if<MacroStep>(&*it);
        if (!macro || !macro->body || !(*macro->body)->elements())
            return nullptr;
        level = (*macro->body)->elements();
    }
    return level;
}

std::vector<Element> withLevel(std::vector<Element> top, const std::vector<quint64> &path, std::vector<Element> level)
{
    if (path.empty())
        return level;
    const auto it = std::ranges::find_if(top, [&](const Element &e) { return header(e).localId == path.front(); });
    auto *macro = it == top.end() ? nullptr : std::get_if<MacroStep>(&*it);
    if (!macro)
        return top;
    Body inner = macro->body ? **macro->body : Body::withLanguage(BodyLanguage::SFC);
    if (!inner.elements())
        inner = Body::withLanguage(BodyLanguage::SFC);
    *inner.elements() = withLevel(*inner.elements(), std::vector<quint64>(path.begin() + 1, path.end()), std::move(level));
    macro->body = inner;
    return top;
}

const std::vector<Element> *SfcPolicy::elements(const ProjectModel &model, const BodyRef &ref) const
{
    const Body *body = model.body(ref);
    if (!body || !body->elements())
        return nullptr;
    const std::vector<Element> *level = levelElements(*body->elements(), m_macroPath);
    if (level && m_macroPath.empty() && body->layoutGenerated) {
        ChartDocument document = readChart(*level);
        layoutChart(document);
        m_display = std::move(document.elements);
        return &m_display;
    }
    return level;
}

namespace {

void addWire(QGraphicsScene &scene, const QList<QPointF> &points)
{
    if (points.size() < 2)
        return;
    QPainterPath path(points.front());
    for (qsizetype i = 1; i < points.size(); ++i)
        path.lineTo(points[i]);
    auto *item = scene.addPath(path, QPen(QColor(0x20, 0x20, 0x20), 1.2));
    item->setZValue(-1);
}

QList<QPointF> waypointsOf(const Connection &c)
{
    QList<QPointF> points;
    for (const Position &p : c.waypoints)
        points << QPointF(p.x, p.y);
    return points;
}

bool isChainElement(const Element &e)
{
    return isBar(e) || std::holds_alternative<Step>(e) || std::holds_alternative<MacroStep>(e)
        || std::holds_alternative<Transition>(e) || std::holds_alternative<JumpStep>(e);
}

// Wires that run sideways: a step to its action block, a variable into a transition's condition.
QList<QPointF> sideWire(const Element &source, const Element &target)
{
    const QRectF from = elementRect(source);
    const QRectF to = elementRect(target);
    if (std::holds_alternative<ActionBlock>(target))
        return {QPointF(from.right(), from.top() + kStepHeight / 2), QPointF(to.left(), from.top() + kStepHeight / 2)};
    if (std::holds_alternative<Transition>(target) && !isChainElement(source)) {
        const QPointF start(from.right(), from.center().y());
        const QPointF end(to.left(), to.center().y());
        return {start, QPointF((start.x() + end.x()) / 2, start.y()), QPointF((start.x() + end.x()) / 2, end.y()), end};
    }
    return {};
}

} // namespace

void SfcPolicy::populate(DiagramScene &scene, const std::vector<Element> &elements)
{
    std::unordered_map<quint64, const Element *> byId;
    std::unordered_set<QString> stepNames;
    for (const Element &e : elements) {
        byId.emplace(header(e).localId, &e);
        if (const auto *step = std::get_if<Step>(&e))
            stepNames.insert(step->name.toLower());
        else if (const auto *macro = std::get_if<MacroStep>(&e); macro && macro->name)
            stepNames.insert(macro->name->toLower());
    }
    // What a label must not run into: the other elements' frames and the wires' segments.
    QList<QRectF> obstacles;
    std::vector<SfcItem *> labelled;
    for (const Element &e : elements) {
        // FBD elements in a chart (Beremiz wires boxes into transitions) are drawn as FBD draws
        // them; everything else of a chart by its own items.
        DiagramItem *item = nullptr;
        SfcItem *chartItem = nullptr;
        if (std::holds_alternative<Block>(e))
            item = boxItemAsDrawn(e, elementRect(e));
        else if (std::holds_alternative<Step>(e) || std::holds_alternative<MacroStep>(e))
            item = chartItem = new StepItem(e);
        else if (std::holds_alternative<Transition>(e))
            item = chartItem = new TransitionItem(e);
        else if (const auto *jump = std::get_if<JumpStep>(&e))
            item = chartItem = new JumpItem(e, stepNames.contains(jump->targetName.toLower()));
        else if (isBar(e))
            item = chartItem = new BarItem(e);
        else if (std::holds_alternative<ActionBlock>(e))
            item = chartItem = new ActionBlockItem(e);
        else
            item = chartItem = new OtherItem(e);
        scene.addElementItem(item);
        obstacles << item->frame();
        if (chartItem && !labelRect(e).isEmpty())
            labelled.push_back(chartItem);
        // Wires, drawn from the input side where TC6 keeps them.
        const Element *target = &e;
        std::vector<const ConnectionPointIn *> points = inputPoints(e);
        for (const ConnectionPointIn *point : points) {
            for (const Connection &c : point->connections) {
                const auto source = byId.find(c.refLocalId);
                // CODESYS wires its jumps into the convergence below them; a jump ends its branch.
                if (source == byId.end() || std::holds_alternative<JumpStep>(*source->second))
                    continue;
                QList<QPointF> line = waypointsOf(c);
                if (line.size() < 2)
                    line = sideWire(*source->second, *target);
                if (line.size() < 2)
                    line = wirePolyline(*source->second, *target);
                addWire(scene, line);
                for (qsizetype i = 1; i < line.size(); ++i)
                    obstacles << QRectF(line[i - 1], line[i]).normalized();
            }
        }
    }
    // A label cut where the next drawing begins (positions from another tool may leave less
    // room than the text needs; the editor's own layouts leave enough).
    for (SfcItem *item : labelled) {
        const QRectF label = labelRect(item->element());
        QList<QRectF> others;
        for (const QRectF &obstacle : obstacles)
            if (obstacle != item->frame())
                others << obstacle;
        item->setLabelRoom(labelRoom(label, others));
    }
}

} // namespace iec::editors::sfc
