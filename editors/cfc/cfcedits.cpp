#include "editors/cfc/cfcedits.h"

#include "editors/cfc/cfcgeometry.h"
#include "editors/common/elementpool.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>

#include <algorithm>
#include <cmath>

namespace iec::editors::cfc {

using namespace model;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("iec::editors::cfc", text); // the context lupdate gives tr() here
}

quint64 largestId(const std::vector<Element> &elements)
{
    quint64 largest = 0;
    for (const Element &e : elements)
        largest = std::max(largest, header(e).localId);
    return largest;
}

double snapped(double value)
{
    return std::round(value / 10) * 10;
}

// Top to bottom, then left to right.
bool topologyBefore(const Element &a, const Element &b)
{
    const Position &p = header(a).position;
    const Position &q = header(b).position;
    return p.y != q.y ? p.y < q.y : p.x < q.x;
}

// Numbers the elements 1..n in `order` (localIds of elements that run).
void number(std::vector<Element> &elements, const std::vector<quint64> &order)
{
    QHash<quint64, quint64> rank;
    for (std::size_t i = 0; i < order.size(); ++i)
        rank.insert(order[i], quint64(i + 1));
    for (Element &e : elements) {
        ElementHeader &h = header(e);
        if (rank.contains(h.localId))
            h.executionOrderId = rank.value(h.localId);
        else if (!runsInOrder(e))
            h.executionOrderId.reset();
    }
}

// The elements that run which `element` reads, looking through inputs, connection marks and
// anything else that does not run.
QSet<quint64> runningSources(const Element &element, const QHash<quint64, const Element *> &byId,
    const QHash<QString, const Element *> &connectors)
{
    QSet<quint64> found;
    QSet<quint64> seen;
    std::vector<const Element *> pending;
    const auto push = [&](const Element *e) {
        const quint64 id = header(*e).localId;
        if (!seen.contains(id)) {
            seen.insert(id);
            pending.push_back(e);
        }
    };
    const auto pushSourcesOf = [&](const Element &e) {
        for (const ConnectionPointIn *point : inputPoints(e))
            for (const Connection &c : point->connections)
                if (const Element *source = byId.value(c.refLocalId))
                    push(source);
        if (const auto *continuation = std::get_if<Continuation>(&e))
            if (const Element *connector = connectors.value(continuation->name.trimmed().toUpper()))
                push(connector);
    };
    pushSourcesOf(element);
    while (!pending.empty()) {
        const Element *e = pending.back();
        pending.pop_back();
        if (runsInOrder(*e))
            found.insert(header(*e).localId);
        else
            pushSourcesOf(*e);
    }
    found.remove(header(element).localId);
    return found;
}

} // namespace

bool runsInOrder(const Element &element)
{
    return std::holds_alternative<Block>(element) || std::holds_alternative<OutVariable>(element)
        || std::holds_alternative<InOutVariable>(element) || std::holds_alternative<Jump>(element)
        || std::holds_alternative<Return>(element) || std::holds_alternative<Label>(element);
}

std::vector<quint64> executionOrder(const std::vector<Element> &elements)
{
    std::vector<const Element *> running;
    for (const Element &e : elements)
        if (runsInOrder(e))
            running.push_back(&e);
    std::stable_sort(running.begin(), running.end(), [](const Element *a, const Element *b) {
        const auto &p = header(*a).executionOrderId;
        const auto &q = header(*b).executionOrderId;
        if (p && q)
            return *p < *q;
        return p && !q;
    });
    std::vector<quint64> order;
    order.reserve(running.size());
    for (const Element *e : running)
        order.push_back(header(*e).localId);
    return order;
}

EditOutcome insertElement(std::vector<Element> &elements, Element element, QPointF at)
{
    ElementHeader &h = header(element);
    h.localId = largestId(elements) + 1;
    h.position = Position {snapped(at.x()), snapped(at.y())};
    const quint64 id = h.localId;
    const bool runs = runsInOrder(element);
    elements.push_back(std::move(element));
    if (runs) {
        std::vector<quint64> order = executionOrder(elements);
        std::erase(order, id);
        order.push_back(id);
        number(elements, order);
    }
    return {{}, {id}};
}

EditOutcome insertElements(std::vector<Element> &elements, std::vector<Element> pasted, QPointF at)
{
    if (pasted.empty())
        return {tr("There is nothing to paste."), {}};
    double left = header(pasted.front()).position.x;
    double top = header(pasted.front()).position.y;
    for (const Element &e : pasted) {
        left = std::min(left, header(e).position.x);
        top = std::min(top, header(e).position.y);
    }
    std::vector<quint64> order = executionOrder(elements);
    const std::vector<quint64> pastedOrder = executionOrder(pasted);
    order.insert(order.end(), pastedOrder.begin(), pastedOrder.end());
    std::vector<quint64> select;
    for (Element &e : pasted) {
        Position &p = header(e).position;
        p = Position {snapped(p.x - left + at.x()), snapped(p.y - top + at.y())};
        select.push_back(header(e).localId);
        elements.push_back(std::move(e));
    }
    number(elements, order);
    return {{}, select};
}

EditOutcome deleteElements(std::vector<Element> &elements, const std::vector<quint64> &localIds)
{
    if (localIds.empty())
        return {tr("Select the elements to delete first."), {}};
    ElementPool pool;
    pool.elements = std::move(elements);
    pool.reindex();
    pool.removeElements(localIds);
    elements = std::move(pool.elements);
    number(elements, executionOrder(elements));
    return {};
}

EditOutcome moveElements(std::vector<Element> &elements, const std::vector<quint64> &localIds, const std::vector<QPointF> &positions)
{
    QHash<quint64, QPointF> to;
    for (std::size_t i = 0; i < localIds.size() && i < positions.size(); ++i)
        to.insert(localIds[i], positions[i]);
    for (Element &e : elements) {
        ElementHeader &h = header(e);
        if (const auto it = to.constFind(h.localId); it != to.cend())
            h.position = Position {it->x(), it->y()};
    }
    return {{}, localIds};
}

EditOutcome nudgeElements(std::vector<Element> &elements, const std::vector<quint64> &localIds, QPointF step)
{
    if (localIds.empty())
        return {tr("Select the elements to move first."), {}};
    const QSet<quint64> moved(localIds.begin(), localIds.end());
    for (Element &e : elements) {
        ElementHeader &h = header(e);
        if (moved.contains(h.localId))
            h.position = Position {std::max(0.0, h.position.x + step.x()), std::max(0.0, h.position.y + step.y())};
    }
    return {{}, localIds};
}

EditOutcome connectPins(std::vector<Element> &elements, quint64 source, const std::optional<QString> &formalParameter,
    quint64 target, int pin)
{
    const auto sourceIt = std::ranges::find_if(elements, [&](const Element &e) { return header(e).localId == source; });
    const auto targetIt = std::ranges::find_if(elements, [&](const Element &e) { return header(e).localId == target; });
    if (sourceIt == elements.end() || targetIt == elements.end())
        return {tr("The wire has no element at one of its ends."), {}};
    if (outputPinIndex(*sourceIt, formalParameter) < 0)
        return {tr("That element has no such output."), {}};
    const auto points = inputPoints(*targetIt);
    if (pin < 0 || pin >= int(points.size()))
        return {tr("That element has no such input."), {}};
    Connection connection;
    connection.refLocalId = source;
    // A box's output is named; a variable's only output is not.
    if (std::holds_alternative<Block>(*sourceIt) && formalParameter && !formalParameter->isEmpty())
        connection.formalParameter = formalParameter;
    else if (const auto *block = std::get_if<Block>(&*sourceIt); block && block->outputVariables.size() == 1)
        connection.formalParameter = block->outputVariables.front().formalParameter;
    ConnectionPointIn *input = points[std::size_t(pin)];
    input->connections = {connection};
    input->expression.reset();
    return {{}, {target}};
}

namespace {

bool isEnPin(const BlockVariable &pin)
{
    return pin.formalParameter.compare(QLatin1String("EN"), Qt::CaseInsensitive) == 0;
}

// Each pin of `now` reads what the pin of that name read in `before`; the pins left read, in
// turn, the old pins (other than EN) left (ADD's IN1 stays MUL's IN1; AND's inputs become TON's
// IN and PT). A new EN starts unwired.
void carryWires(std::vector<BlockVariable> &now, const std::vector<BlockVariable> &before)
{
    const auto sameName = [](const BlockVariable &a, const BlockVariable &b) {
        return a.formalParameter.compare(b.formalParameter, Qt::CaseInsensitive) == 0;
    };
    std::vector<const BlockVariable *> left;
    for (const BlockVariable &old : before)
        if (!isEnPin(old) && std::ranges::none_of(now, [&](const BlockVariable &pin) { return sameName(pin, old); }))
            left.push_back(&old);
    std::size_t next = 0;
    for (BlockVariable &pin : now) {
        const auto same = std::ranges::find_if(before, [&](const BlockVariable &old) { return sameName(pin, old); });
        const BlockVariable *from = same != before.end() ? &*same : nullptr;
        if (!from && !isEnPin(pin) && next < left.size())
            from = left[next++];
        if (from && from->connectionPointIn && pin.connectionPointIn)
            pin.connectionPointIn->connections = from->connectionPointIn->connections;
    }
}

} // namespace

EditOutcome replaceBlock(std::vector<Element> &elements, quint64 localId, Block fresh)
{
    const auto it = std::ranges::find_if(elements, [&](const Element &e) { return header(e).localId == localId; });
    const auto *old = it != elements.end() ? std::get_if<Block>(&*it) : nullptr;
    if (!old)
        return {tr("The box is gone."), {}};
    carryWires(fresh.inputVariables, old->inputVariables);
    carryWires(fresh.inOutVariables, old->inOutVariables);
    static_cast<ElementHeader &>(fresh) = static_cast<const ElementHeader &>(*old);
    if (fresh.instanceName && old->instanceName)
        fresh.instanceName = old->instanceName;
    QSet<QString> outputs;
    for (const BlockVariable &pin : fresh.outputVariables)
        outputs.insert(pin.formalParameter.toUpper());
    for (const BlockVariable &pin : fresh.inOutVariables)
        outputs.insert(pin.formalParameter.toUpper());
    *it = std::move(fresh);
    // A reader of an output the new box does not have (ENO taken away, Q of a box that became ADD)
    // would name a pin that is not there: its wire goes.
    for (Element &e : elements)
        for (ConnectionPointIn *input : inputPoints(e))
            std::erase_if(input->connections, [&](const Connection &c) {
                return c.refLocalId == localId && c.formalParameter && !c.formalParameter->isEmpty()
                    && !outputs.contains(c.formalParameter->toUpper());
            });
    return {{}, {localId}};
}

EditOutcome orderByDataFlow(std::vector<Element> &elements)
{
    QHash<quint64, const Element *> byId;
    QHash<QString, const Element *> connectors;
    for (const Element &e : elements) {
        byId.insert(header(e).localId, &e);
        if (const auto *connector = std::get_if<Connector>(&e))
            connectors.insert(connector->name.trimmed().toUpper(), &e);
    }
    std::vector<const Element *> running;
    for (const Element &e : elements)
        if (runsInOrder(e))
            running.push_back(&e);
    // Kahn's algorithm; among the ready elements the topmost, leftmost runs first. When only a
    // loop is left, its topmost, leftmost element runs first and reads the loop's old value.
    QHash<quint64, QSet<quint64>> waitsFor;
    for (const Element *e : running)
        waitsFor.insert(header(*e).localId, runningSources(*e, byId, connectors));
    std::vector<quint64> order;
    std::vector<const Element *> left = running;
    std::stable_sort(left.begin(), left.end(), [](const Element *a, const Element *b) { return topologyBefore(*a, *b); });
    // Whether `id` waits, through the elements still left, for itself: it is on a loop.
    const auto onLoop = [&](quint64 id) {
        QSet<quint64> seen;
        std::vector<quint64> pending(waitsFor.value(id).begin(), waitsFor.value(id).end());
        while (!pending.empty()) {
            const quint64 next = pending.back();
            pending.pop_back();
            if (next == id)
                return true;
            if (seen.contains(next))
                continue;
            seen.insert(next);
            for (quint64 further : waitsFor.value(next))
                pending.push_back(further);
        }
        return false;
    };
    while (!left.empty()) {
        auto ready = std::ranges::find_if(left, [&](const Element *e) { return waitsFor.value(header(*e).localId).isEmpty(); });
        if (ready == left.end())
            ready = std::ranges::find_if(left, [&](const Element *e) { return onLoop(header(*e).localId); });
        if (ready == left.end())
            ready = left.begin();
        const quint64 id = header(**ready).localId;
        order.push_back(id);
        left.erase(ready);
        for (auto it = waitsFor.begin(); it != waitsFor.end(); ++it)
            it->remove(id);
    }
    number(elements, order);
    return {};
}

EditOutcome orderByTopology(std::vector<Element> &elements)
{
    std::vector<const Element *> running;
    for (const Element &e : elements)
        if (runsInOrder(e))
            running.push_back(&e);
    std::stable_sort(running.begin(), running.end(), [](const Element *a, const Element *b) { return topologyBefore(*a, *b); });
    std::vector<quint64> order;
    for (const Element *e : running)
        order.push_back(header(*e).localId);
    number(elements, order);
    return {};
}

EditOutcome moveInOrder(std::vector<Element> &elements, const std::vector<quint64> &localIds, OrderMove move)
{
    std::vector<quint64> order = executionOrder(elements);
    const QSet<quint64> selected(localIds.begin(), localIds.end());
    const auto isSelected = [&](quint64 id) { return selected.contains(id); };
    if (std::ranges::none_of(order, isSelected))
        return {tr("Select an element that has an execution order number (a box, an output, a jump, a return or a label)."), {}};
    switch (move) {
    case OrderMove::Earlier:
        for (std::size_t i = 1; i < order.size(); ++i)
            if (isSelected(order[i]) && !isSelected(order[i - 1]))
                std::swap(order[i], order[i - 1]);
        break;
    case OrderMove::Later:
        for (std::size_t i = order.size() - 1; i-- > 0;)
            if (isSelected(order[i]) && !isSelected(order[i + 1]))
                std::swap(order[i], order[i + 1]);
        break;
    case OrderMove::ToFront:
        std::stable_partition(order.begin(), order.end(), isSelected);
        break;
    case OrderMove::ToBack:
        std::stable_partition(order.begin(), order.end(), [&](quint64 id) { return !isSelected(id); });
        break;
    }
    number(elements, order);
    return {{}, localIds};
}

EditOutcome setOrderNumber(std::vector<Element> &elements, quint64 localId, int numberWanted)
{
    std::vector<quint64> order = executionOrder(elements);
    if (std::ranges::find(order, localId) == order.end())
        return {tr("Only boxes, outputs, jumps, returns and labels have an execution order number."), {}};
    if (numberWanted < 1 || numberWanted > int(order.size()))
        return {tr("The number must lie between 1 and %1.").arg(order.size()), {}};
    std::erase(order, localId);
    order.insert(order.begin() + (numberWanted - 1), localId);
    number(elements, order);
    return {{}, {localId}};
}

} // namespace iec::editors::cfc
