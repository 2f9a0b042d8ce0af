#include "editors/ld/ldedits.h"

#include "editors/ld/ldgraph.h"
#include "editors/ld/ldtree.h"

#include <QCoreApplication>

#include <algorithm>
#include <set>

namespace iec::editors::ld {

using namespace model;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("iec::editors::ld::LdEdits", text);
}

LdEditResult refuse(const char *text)
{
    return {tr(text), {}};
}

// The network the cursor is in, or a refusal.
std::optional<QString> checkNetwork(const LadderDocument &document, int network, bool structural)
{
    if (network < 0 || network >= int(document.networks.size()))
        return QCoreApplication::translate("iec::editors::ld::LdEdits", "There is no network here. Insert a network first (Network After).");
    if (structural && document.networks[std::size_t(network)].freehand)
        return QCoreApplication::translate("iec::editors::ld::LdEdits", "This network is drawn freely by another tool, not as a rung: change its elements one by one "
                  "(their names, negation), or delete it and draw it again.");
    return std::nullopt;
}

// ---- elements in the pool

// Moves a new element next to the one before it in the rung, so that the file lists a network's
// elements in rung order (the order the interpreter runs boxes and coils of an unplaced body).
void placeInFile(LadderDocument &document, int network, quint64 id)
{
    const LdNetwork &net = document.networks[std::size_t(network)];
    const std::vector<quint64> order = rungElements(net.rung);
    const auto at = std::ranges::find(order, id);
    int target = -1;
    if (at != order.end() && at != order.begin())
        target = document.indexOf(*(at - 1)) + 1;
    if (target < 0) {
        target = int(document.elements.size());
        for (quint64 member : net.members)
            if (member != id)
                target = std::min(target, document.indexOf(member));
    }
    const int from = document.indexOf(id);
    if (from < 0 || target == from || target == from + 1)
        return;
    document.moveElement(from, target > from ? target - 1 : target);
}

// Moves an element right before another in the file (a box's variables before the box).
void placeBefore(LadderDocument &document, quint64 id, quint64 anchor)
{
    const int from = document.indexOf(id);
    const int to = document.indexOf(anchor);
    if (from < 0 || to < 0)
        return;
    document.moveElement(from, from < to ? to - 1 : to);
}

quint64 addMember(LadderDocument &document, int network, Element element)
{
    const quint64 id = document.add(std::move(element));
    document.networks[std::size_t(network)].members.push_back(id);
    return id;
}

Contact newContact()
{
    Contact contact;
    contact.variable = kPlaceholder;
    return contact;
}

Coil newCoil()
{
    Coil coil;
    coil.variable = kPlaceholder;
    return coil;
}

// A variable on a box's side pin, wired to it.
quint64 addSideVariable(LadderDocument &document, int network, quint64 box, int pin, const QString &text = kPlaceholder)
{
    InVariable variable;
    variable.expression = text;
    variable.connectionPointOut.emplace();
    const quint64 id = addMember(document, network, std::move(variable));
    auto &block = std::get<Block>(*document.element(box));
    BlockVariable &input = block.inputVariables[std::size_t(pin)];
    if (!input.connectionPointIn)
        input.connectionPointIn.emplace();
    input.connectionPointIn->connections = {Connection {id, std::nullopt, {}, {}, {}, {}}};
    return id;
}

// ---- where a series insertion goes

struct SeriesSpot {
    std::vector<int> path; // of the series
    int index = 0;
};

std::optional<SeriesSpot> seriesSpot(const LadderDocument &document, const LdCursor &cursor)
{
    const LdNetwork &network = document.networks[std::size_t(cursor.network)];
    switch (cursor.kind) {
    case LdCursor::Kind::Network:
        return SeriesSpot {{}, tree::outputTail(document, network.rung)};
    case LdCursor::Kind::Wire: {
        const RungNode *series = tree::nodeAt(network.rung, cursor.wire.path);
        if (!series || series->kind != RungNode::Kind::Series || cursor.wire.index > int(series->children.size()))
            return std::nullopt;
        return SeriesSpot {cursor.wire.path, cursor.wire.index};
    }
    case LdCursor::Kind::Element:
        if (const auto place = tree::placeOf(network.rung, cursor.element()))
            return SeriesSpot {place->seriesPath, place->index};
        return std::nullopt;
    }
    return std::nullopt;
}

LdEditResult insertInSeries(LadderDocument &document, const LdCursor &cursor, Element element)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    const std::optional<SeriesSpot> spot = seriesSpot(document, cursor);
    if (!spot)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Put the cursor on an element or on a wire of the rung first."));
    const quint64 id = addMember(document, cursor.network, std::move(element));
    LdNetwork &network = document.networks[std::size_t(cursor.network)];
    RungNode *series = tree::nodeAt(network.rung, spot->path);
    series->children.insert(series->children.begin() + spot->index, RungNode::element(id));
    tree::normalize(network.rung);
    placeInFile(document, cursor.network, id);
    return {{}, LdCursor::atElement(cursor.network, id)};
}

// Adds an output parallel to the outputs at the end of the rung (below the one at the cursor).
LdEditResult insertOutput(LadderDocument &document, const LdCursor &cursor, Element element)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    const quint64 id = addMember(document, cursor.network, std::move(element));
    LdNetwork &network = document.networks[std::size_t(cursor.network)];
    RungNode &rung = network.rung;
    const int tail = tree::outputTail(document, rung);
    const int size = int(rung.children.size());
    if (tail == size) {
        rung.children.push_back(RungNode::element(id));
    } else if (tail == size - 1 && rung.children.back().kind == RungNode::Kind::Parallel) {
        RungNode &outputs = rung.children.back();
        int after = int(outputs.children.size()) - 1;
        if (cursor.kind == LdCursor::Kind::Element) {
            if (const auto place = tree::placeOf(rung, cursor.element()); place && place->seriesPath.size() >= 2
                && place->seriesPath.front() == size - 1)
                after = place->seriesPath[1];
        }
        outputs.children.insert(outputs.children.begin() + after + 1, RungNode::series({RungNode::element(id)}));
    } else {
        std::vector<RungNode> existing(std::make_move_iterator(rung.children.begin() + tail),
            std::make_move_iterator(rung.children.end()));
        rung.children.erase(rung.children.begin() + tail, rung.children.end());
        rung.children.push_back(RungNode::parallel({RungNode::series(std::move(existing)), RungNode::series({RungNode::element(id)})}));
    }
    tree::normalize(rung);
    placeInFile(document, cursor.network, id);
    return {{}, LdCursor::atElement(cursor.network, id)};
}

// The deepest series that holds all the elements, and the range of its children they are in.
struct SeriesRange {
    std::vector<int> path;
    int first = 0;
    int last = 0;
};

std::optional<SeriesRange> rangeOf(const RungNode &rung, const std::vector<quint64> &elements)
{
    std::vector<std::vector<int>> paths;
    for (quint64 id : elements) {
        std::vector<int> path = pathOf(rung, id);
        if (path.empty())
            return std::nullopt;
        paths.push_back(std::move(path));
    }
    if (paths.empty())
        return std::nullopt;
    std::size_t common = paths.front().size() - 1;
    for (const auto &path : paths) {
        std::size_t same = 0;
        while (same < common && same < path.size() - 1 && path[same] == paths.front()[same])
            ++same;
        common = same;
    }
    std::vector<int> prefix(paths.front().begin(), paths.front().begin() + long(common));
    // The range's series: the prefix itself when it names a series, else the series around it.
    while (!prefix.empty() && tree::nodeAt(rung, prefix)->kind != RungNode::Kind::Series)
        prefix.pop_back();
    SeriesRange range {prefix, std::numeric_limits<int>::max(), -1};
    for (const auto &path : paths) {
        const int child = path[prefix.size()];
        range.first = std::min(range.first, child);
        range.last = std::max(range.last, child);
    }
    return range;
}

// The box a side element serves (the element wired into one of its pins), 0 for none.
quint64 boxServedBy(const LadderDocument &document, quint64 side)
{
    for (const Element &e : document.elements) {
        const auto *block = std::get_if<Block>(&e);
        if (!block)
            continue;
        for (const BlockVariable &v : block->inputVariables)
            if (v.connectionPointIn)
                for (const Connection &c : v.connectionPointIn->connections)
                    if (c.refLocalId == side)
                        return block->localId;
    }
    return 0;
}

// Every element that hangs on a box's side pins (recursively for operator boxes) and its
// assignments.
std::vector<quint64> sideElements(const LadderDocument &document, quint64 box)
{
    std::vector<quint64> result;
    const LdGraph graph(document.elements);
    const int index = document.indexOf(box);
    if (index < 0)
        return result;
    const RungPins pins = document.pinsOf(box);
    std::vector<std::pair<std::size_t, bool>> todo {{std::size_t(index), true}};
    while (!todo.empty()) {
        const auto [i, top] = todo.back();
        todo.pop_back();
        for (const LdGraph::Wire &wire : graph.inputs(i)) {
            if (top && wire.pin == pins.input)
                continue;
            result.push_back(graph.localId(wire.source));
            if (std::holds_alternative<Block>(graph.element(wire.source)))
                todo.emplace_back(wire.source, false);
        }
        if (top)
            for (const LdGraph::Reader &reader : graph.readers(i))
                if (reader.sourcePin != pins.output && std::holds_alternative<OutVariable>(graph.element(reader.target)))
                    result.push_back(graph.localId(reader.target));
    }
    return result;
}

const Block *blockAt(const LadderDocument &document, quint64 id)
{
    const Element *e = document.element(id);
    return e ? std::get_if<Block>(e) : nullptr;
}

// The box at the cursor: the element itself, or the box a side variable at the cursor serves.
quint64 boxAtCursor(const LadderDocument &document, const LdCursor &cursor)
{
    if (cursor.kind != LdCursor::Kind::Element)
        return 0;
    if (blockAt(document, cursor.element()))
        return cursor.element();
    return boxServedBy(document, cursor.element());
}

} // namespace

std::vector<int> pathOf(const RungNode &rung, quint64 localId)
{
    const auto place = tree::placeOf(rung, localId);
    if (!place)
        return {};
    std::vector<int> path = place->seriesPath;
    path.push_back(place->index);
    return path;
}

// ---- networks

LdEditResult insertNetwork(LadderDocument &document, const LdCursor &cursor, bool after)
{
    const int count = int(document.networks.size());
    const int at = count == 0 ? 0 : std::clamp(cursor.network + (after ? 1 : 0), 0, count);
    // In the file, the new network's rails go after the networks before it.
    int fileIndex = 0;
    for (int n = 0; n < at; ++n)
        for (quint64 id : document.networks[std::size_t(n)].members)
            fileIndex = std::max(fileIndex, document.indexOf(id) + 1);
    LdNetwork network;
    network.leftRail = document.add(LeftPowerRail {}, fileIndex);
    network.rightRail = document.add(RightPowerRail {}, fileIndex + 1);
    network.members = {network.leftRail, network.rightRail};
    document.networks.insert(document.networks.begin() + at, std::move(network));
    return {{}, LdCursor::atNetwork(at)};
}

LdEditResult setNetworkLabel(LadderDocument &document, int index, const QString &text)
{
    if (const auto problem = checkNetwork(document, index, false))
        return {*problem, {}};
    const QString label = text.trimmed();
    LdNetwork &network = document.networks[std::size_t(index)];
    if (label.isEmpty()) {
        if (network.label)
            document.remove({network.label});
        network.label = 0;
        return {{}, LdCursor::atNetwork(index)};
    }
    for (std::size_t n = 0; n < document.networks.size(); ++n) {
        const quint64 other = document.networks[n].label;
        if (int(n) != index && other && std::get<Label>(*document.element(other)).label.compare(label, Qt::CaseInsensitive) == 0)
            return {QCoreApplication::translate("iec::editors::ld::LdEdits", "Network %1 has the label %2 already: labels name one network each.").arg(n + 1).arg(label), {}};
    }
    if (!network.label) {
        Label element;
        element.label = label;
        network.label = addMember(document, index, std::move(element));
        const int first = document.indexOf(network.members.front());
        document.moveElement(document.indexOf(network.label), std::max(0, first));
    } else
        std::get<Label>(*document.element(network.label)).label = label;
    return {{}, LdCursor::atNetwork(index)};
}

LdEditResult setNetworkComment(LadderDocument &document, int index, const QString &text)
{
    if (const auto problem = checkNetwork(document, index, false))
        return {*problem, {}};
    LdNetwork &network = document.networks[std::size_t(index)];
    if (text.trimmed().isEmpty()) {
        if (network.comment)
            document.remove({network.comment});
        network.comment = 0;
    } else if (network.comment) {
        std::get<Comment>(*document.element(network.comment)).content.text = text;
    } else {
        Comment comment;
        comment.content.text = text;
        network.comment = addMember(document, index, std::move(comment));
    }
    return {{}, LdCursor::atNetwork(index)};
}

// ---- rung elements

LdEditResult insertContact(LadderDocument &document, const LdCursor &cursor)
{
    return insertInSeries(document, cursor, newContact());
}

LdEditResult insertParallelContact(LadderDocument &document, const LdCursor &cursor, bool below)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    if (cursor.kind != LdCursor::Kind::Element)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select the contacts (shift-click for a range) that the parallel contact goes around."));
    LdNetwork &network = document.networks[std::size_t(cursor.network)];
    const std::optional<SeriesRange> range = rangeOf(network.rung, cursor.elements);
    if (!range)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select the contacts (shift-click for a range) that the parallel contact goes around."));
    RungNode *series = tree::nodeAt(network.rung, range->path);
    for (int i = range->first; i <= range->last; ++i)
        if (tree::endsInOutput(document, series->children[std::size_t(i)]))
            return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "A parallel contact goes around contacts and boxes; for another output use Coil."));
    const quint64 id = addMember(document, cursor.network, newContact());
    series = tree::nodeAt(network.rung, range->path);
    std::vector<RungNode> around(std::make_move_iterator(series->children.begin() + range->first),
        std::make_move_iterator(series->children.begin() + range->last + 1));
    series->children.erase(series->children.begin() + range->first, series->children.begin() + range->last + 1);
    RungNode added = RungNode::series({RungNode::element(id)});
    RungNode kept = RungNode::series(std::move(around));
    RungNode parallel = below ? RungNode::parallel({std::move(kept), std::move(added)})
                              : RungNode::parallel({std::move(added), std::move(kept)});
    series->children.insert(series->children.begin() + range->first, std::move(parallel));
    tree::normalize(network.rung);
    placeInFile(document, cursor.network, id);
    return {{}, LdCursor::atElement(cursor.network, id)};
}

LdEditResult insertCoil(LadderDocument &document, const LdCursor &cursor)
{
    return insertOutput(document, cursor, newCoil());
}

LdEditResult insertJump(LadderDocument &document, const LdCursor &cursor, const QString &label)
{
    Jump jump;
    jump.label = label.trimmed().isEmpty() ? kPlaceholder : label.trimmed();
    return insertOutput(document, cursor, std::move(jump));
}

LdEditResult insertReturn(LadderDocument &document, const LdCursor &cursor)
{
    return insertOutput(document, cursor, Return {});
}

LdEditResult insertBox(LadderDocument &document, const LdCursor &cursor, const BoxSpec &spec)
{
    if (spec.typeName.trimmed().isEmpty())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Choose the function or function block the box calls."));
    Block block;
    block.typeName = spec.typeName.trimmed();
    if (spec.functionBlock)
        block.instanceName = kPlaceholder;
    const auto pin = [](const QString &name) {
        BlockVariable variable;
        variable.formalParameter = name;
        return variable;
    };
    if (spec.withEn) {
        block.inputVariables.push_back(pin(QStringLiteral("EN")));
        block.outputVariables.push_back(pin(QStringLiteral("ENO")));
    }
    for (const QString &name : spec.inputs)
        block.inputVariables.push_back(pin(name));
    for (const QString &name : spec.outputs)
        block.outputVariables.push_back(pin(name));
    RungPins pins {spec.withEn ? 0 : spec.rungInput, spec.withEn ? 0 : (spec.rungOutput < 0 ? -1 : spec.rungOutput)};
    if (pins.input < 0 || pins.input >= int(block.inputVariables.size()))
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "This box has no input the rung could drive: use the box with EN."));
    LdEditResult result = insertInSeries(document, cursor, std::move(block));
    if (!result.ok())
        return result;
    const quint64 id = result.cursor.element();
    document.boxPins[id] = pins;
    const int inputs = int(std::get<Block>(*document.element(id)).inputVariables.size());
    // The side variables go just before their box in the file, in pin order.
    for (int p = 0; p < inputs; ++p)
        if (p != pins.input)
            placeBefore(document, addSideVariable(document, cursor.network, id, p), id);
    return result;
}

// ---- at a box's pins

LdEditResult insertBoxInput(LadderDocument &document, const LdCursor &cursor)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    const quint64 box = boxAtCursor(document, cursor);
    const Block *block = blockAt(document, box);
    if (!block)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select a box (or a variable on its inputs) first."));
    if (!isExtensible(block->typeName))
        return {QCoreApplication::translate("iec::editors::ld::LdEdits", "%1 has a fixed number of inputs.").arg(block->typeName), {}};
    // The next number after the highest numbered input (IN1, IN2 → IN3; MUX's IN0, IN1 → IN2).
    int highest = 0;
    int insertAt = int(block->inputVariables.size());
    for (int p = 0; p < int(block->inputVariables.size()); ++p) {
        const QString name = block->inputVariables[std::size_t(p)].formalParameter;
        if (name.startsWith(QLatin1String("IN"), Qt::CaseInsensitive)) {
            bool ok = false;
            const int number = name.mid(2).toInt(&ok);
            if (ok) {
                highest = std::max(highest, number);
                insertAt = p + 1;
            }
        }
    }
    auto &mutableBlock = std::get<Block>(*document.element(box));
    BlockVariable added;
    added.formalParameter = QStringLiteral("IN%1").arg(highest + 1);
    mutableBlock.inputVariables.insert(mutableBlock.inputVariables.begin() + insertAt, std::move(added));
    RungPins &pins = document.boxPins[box];
    if (pins.input >= insertAt)
        ++pins.input;
    const quint64 variable = addSideVariable(document, cursor.network, box, insertAt);
    placeBefore(document, variable, box);
    return {{}, LdCursor::atElement(cursor.network, variable)};
}

LdEditResult insertBoxAssignment(LadderDocument &document, const LdCursor &cursor)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    const quint64 box = boxAtCursor(document, cursor);
    const Block *block = blockAt(document, box);
    if (!block)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select a box first."));
    const RungPins pins = document.pinsOf(box);
    const LdGraph graph(document.elements);
    std::set<int> taken;
    for (const LdGraph::Reader &reader : graph.readers(std::size_t(document.indexOf(box))))
        taken.insert(reader.sourcePin);
    for (int p = 0; p < int(block->outputVariables.size()); ++p) {
        const BlockVariable &output = block->outputVariables[std::size_t(p)];
        const bool hasExpression = output.connectionPointOut && output.connectionPointOut->expression;
        if (p == pins.output || taken.contains(p) || hasExpression)
            continue;
        OutVariable assignment;
        assignment.expression = kPlaceholder;
        assignment.connectionPointIn.emplace();
        assignment.connectionPointIn->connections = {Connection {box, output.formalParameter, {}, {}, {}, {}}};
        const quint64 id = addMember(document, cursor.network, std::move(assignment));
        placeInFile(document, cursor.network, id);
        return {{}, LdCursor::atElement(cursor.network, id)};
    }
    return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Every output of this box has an assignment already."));
}

LdEditResult insertOperatorAtInput(LadderDocument &document, const LdCursor &cursor, const BoxSpec &spec)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    const quint64 variable = cursor.kind == LdCursor::Kind::Element ? cursor.element() : 0;
    const quint64 box = boxServedBy(document, variable);
    if (!box || !document.element(variable) || !std::holds_alternative<InVariable>(*document.element(variable)))
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select a variable on a box's input first: the operator goes in front of it."));
    if (spec.inputs.isEmpty() || spec.outputs.isEmpty())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "An operator needs an input and an output."));
    Block op;
    op.typeName = spec.typeName;
    for (const QString &name : spec.inputs) {
        BlockVariable input;
        input.formalParameter = name;
        op.inputVariables.push_back(std::move(input));
    }
    for (const QString &name : spec.outputs) {
        BlockVariable output;
        output.formalParameter = name;
        output.connectionPointOut.emplace();
        op.outputVariables.push_back(std::move(output));
    }
    const quint64 opId = addMember(document, cursor.network, std::move(op));
    // The box now reads the operator where it read the variable; the variable feeds the operator.
    auto &served = std::get<Block>(*document.element(box));
    for (BlockVariable &input : served.inputVariables)
        if (input.connectionPointIn)
            for (Connection &c : input.connectionPointIn->connections)
                if (c.refLocalId == variable)
                    c = Connection {opId, spec.outputs.front(), {}, {}, {}, {}};
    auto &opBlock = std::get<Block>(*document.element(opId));
    opBlock.inputVariables.front().connectionPointIn.emplace();
    opBlock.inputVariables.front().connectionPointIn->connections = {Connection {variable, std::nullopt, {}, {}, {}, {}}};
    placeBefore(document, opId, box);
    for (int p = 1; p < int(spec.inputs.size()); ++p)
        placeBefore(document, addSideVariable(document, cursor.network, opId, p), opId);
    return {{}, LdCursor::atElement(cursor.network, opId)};
}

// ---- properties

LdEditResult toggleNegation(LadderDocument &document, const LdCursor &cursor)
{
    Element *e = cursor.kind == LdCursor::Kind::Element ? document.element(cursor.element()) : nullptr;
    if (auto *contact = e ? std::get_if<Contact>(e) : nullptr)
        contact->negated = !contact->negated;
    else if (auto *coil = e ? std::get_if<Coil>(e) : nullptr) {
        coil->negated = !coil->negated;
        coil->storage = StorageModifier::None; // a set or reset coil cannot be negated
    } else
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select a contact or a coil to negate."));
    return {{}, cursor};
}

LdEditResult cycleSetReset(LadderDocument &document, const LdCursor &cursor)
{
    Element *e = cursor.kind == LdCursor::Kind::Element ? document.element(cursor.element()) : nullptr;
    auto *coil = e ? std::get_if<Coil>(e) : nullptr;
    if (!coil)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select a coil: Set/Reset makes it a set (S) or reset (R) coil."));
    switch (coil->storage) {
    case StorageModifier::None: coil->storage = StorageModifier::Set; break;
    case StorageModifier::Set: coil->storage = StorageModifier::Reset; break;
    case StorageModifier::Reset: coil->storage = StorageModifier::None; break;
    }
    coil->negated = false;
    return {{}, cursor};
}

LdEditResult cycleEdge(LadderDocument &document, const LdCursor &cursor)
{
    Element *e = cursor.kind == LdCursor::Kind::Element ? document.element(cursor.element()) : nullptr;
    EdgeModifier *edge = nullptr;
    if (auto *contact = e ? std::get_if<Contact>(e) : nullptr)
        edge = &contact->edge;
    else if (auto *coil = e ? std::get_if<Coil>(e) : nullptr)
        edge = &coil->edge;
    if (!edge)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select a contact or a coil: an edge makes it react to a rising (P) or falling (N) edge."));
    *edge = *edge == EdgeModifier::None ? EdgeModifier::Rising
        : *edge == EdgeModifier::Rising ? EdgeModifier::Falling
                                        : EdgeModifier::None;
    return {{}, cursor};
}

QString elementText(const LadderDocument &document, quint64 localId)
{
    const Element *e = document.element(localId);
    if (!e)
        return {};
    if (const auto *contact = std::get_if<Contact>(e))
        return contact->variable;
    if (const auto *coil = std::get_if<Coil>(e))
        return coil->variable;
    if (const auto *block = std::get_if<Block>(e))
        return block->instanceName.value_or(block->typeName);
    if (const auto *in = std::get_if<InVariable>(e))
        return in->expression;
    if (const auto *out = std::get_if<OutVariable>(e))
        return out->expression;
    if (const auto *jump = std::get_if<Jump>(e))
        return jump->label;
    if (const auto *label = std::get_if<Label>(e))
        return label->label;
    return {};
}

LdEditResult setElementText(LadderDocument &document, quint64 localId, const QString &typed)
{
    const QString text = typed.trimmed();
    Element *e = document.element(localId);
    const int network = document.networkOf(localId);
    if (!e)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "The element is gone."));
    if (text.isEmpty())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Type a name (or press Esc to keep the old one)."));
    if (auto *contact = std::get_if<Contact>(e))
        contact->variable = text;
    else if (auto *coil = std::get_if<Coil>(e))
        coil->variable = text;
    else if (auto *block = std::get_if<Block>(e)) {
        if (block->instanceName)
            block->instanceName = text;
        else
            block->typeName = text;
    } else if (auto *in = std::get_if<InVariable>(e))
        in->expression = text;
    else if (auto *out = std::get_if<OutVariable>(e))
        out->expression = text;
    else if (auto *jump = std::get_if<Jump>(e))
        jump->label = text;
    else if (auto *label = std::get_if<Label>(e))
        label->label = text;
    else
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "This element has no name to type."));
    return {{}, LdCursor::atElement(network, localId)};
}

// ---- delete

LdEditResult deleteAtCursor(LadderDocument &document, const LdCursor &cursor)
{
    if (const auto problem = checkNetwork(document, cursor.network, false))
        return {*problem, {}};
    LdNetwork &network = document.networks[std::size_t(cursor.network)];
    if (cursor.kind == LdCursor::Kind::Network) {
        const std::vector<quint64> members = network.members;
        document.networks.erase(document.networks.begin() + cursor.network);
        document.remove(members);
        return {{}, LdCursor::atNetwork(std::max(0, std::min(cursor.network, int(document.networks.size()) - 1)))};
    }
    if (cursor.kind == LdCursor::Kind::Wire)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select an element or a network to delete."));
    std::vector<quint64> gone;
    std::vector<std::pair<quint64, int>> replacements; // (box, pin) that lost an operator box
    std::optional<tree::Place> firstPlace;
    for (quint64 id : cursor.elements) {
        if (!document.element(id))
            continue;
        if (id == network.leftRail || id == network.rightRail)
            return refuse(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "The power rails belong to the network: delete the network to remove them."));
        if (id == network.label)
            network.label = 0;
        if (id == network.comment)
            network.comment = 0;
        // A variable on a box's pin is not removed but emptied: the pin keeps a "???" to type.
        if (const quint64 box = boxServedBy(document, id); box && !tree::placeOf(network.rung, id)) {
            if (auto *variable = std::get_if<InVariable>(document.element(id))) {
                variable->expression = kPlaceholder;
                continue;
            }
            const LdGraph graph(document.elements);
            for (const LdGraph::Wire &wire : graph.inputs(std::size_t(document.indexOf(box))))
                if (graph.localId(wire.source) == id)
                    replacements.emplace_back(box, wire.pin);
        }
        gone.push_back(id);
        if (blockAt(document, id))
            for (quint64 side : sideElements(document, id))
                gone.push_back(side);
        if (const auto place = tree::placeOf(network.rung, id)) {
            if (!firstPlace)
                firstPlace = place;
            RungNode *series = tree::nodeAt(network.rung, place->seriesPath);
            series->children.erase(series->children.begin() + place->index);
        }
    }
    tree::normalize(network.rung);
    document.remove(gone);
    for (const auto &[box, pin] : replacements)
        placeBefore(document, addSideVariable(document, cursor.network, box, pin), box);
    LdCursor next = LdCursor::atNetwork(cursor.network);
    if (firstPlace) {
        const RungNode *series = tree::nodeAt(network.rung, firstPlace->seriesPath);
        if (series && series->kind == RungNode::Kind::Series && firstPlace->index <= int(series->children.size()))
            next = LdCursor::atWire(cursor.network, WirePoint {firstPlace->seriesPath, firstPlace->index, {}});
    }
    return {{}, next};
}

// ---- cursor

LdCursor validCursor(const LadderDocument &document, const LdCursor &cursor)
{
    if (document.networks.empty())
        return LdCursor::atNetwork(0);
    const int network = std::clamp(cursor.network, 0, int(document.networks.size()) - 1);
    const LdNetwork &net = document.networks[std::size_t(network)];
    switch (cursor.kind) {
    case LdCursor::Kind::Network:
        return LdCursor::atNetwork(network);
    case LdCursor::Kind::Element: {
        std::vector<quint64> kept;
        for (quint64 id : cursor.elements)
            if (std::ranges::find(net.members, id) != net.members.end())
                kept.push_back(id);
        if (kept.empty())
            return LdCursor::atNetwork(network);
        return {LdCursor::Kind::Element, network, kept, {}};
    }
    case LdCursor::Kind::Wire: {
        const RungNode *series = tree::nodeAt(net.rung, cursor.wire.path);
        if (!series || series->kind != RungNode::Kind::Series || cursor.wire.index > int(series->children.size()))
            return LdCursor::atNetwork(network);
        return LdCursor::atWire(network, cursor.wire);
    }
    }
    return LdCursor::atNetwork(network);
}

} // namespace iec::editors::ld
