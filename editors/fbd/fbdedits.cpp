#include "editors/fbd/fbdedits.h"

#include "editors/fbd/fbdeditsupport.h"

#include <QCoreApplication>

#include <algorithm>

namespace iec::editors::fbd {

using namespace model;
using Kind = FbdCursor::Kind;

// The helpers the edits share with the clipboard (fbdclipboard.cpp): declared in
// fbdeditsupport.h.
namespace detail {

// A refusal; `text` is marked with QT_TRANSLATE_NOOP in the FbdEdits context.
FbdEditResult refuse(const char *text)
{
    return {QCoreApplication::translate("iec::editors::fbd::FbdEdits", text), {}};
}

// Problems that stop every edit of a network's structure.
std::optional<QString> checkNetwork(const FbdDocument &document, int index, bool structural)
{
    if (index < 0 || index >= int(document.networks.size()))
        return QCoreApplication::translate("iec::editors::fbd::FbdEdits", "Insert a network first (Network After, Ctrl+T).");
    if (structural && document.networks[std::size_t(index)].freehand)
        return QCoreApplication::translate("iec::editors::fbd::FbdEdits", "This network was drawn freely in another tool: it is not a tree of boxes, so boxes, inputs and outputs cannot be inserted into it. Its elements can still be renamed, negated or deleted.");
    return std::nullopt;
}

quint64 addTo(FbdDocument &document, FbdNetwork &network, Element element)
{
    const quint64 id = document.add(std::move(element));
    network.members.push_back(id);
    return id;
}

quint64 newVariable(FbdDocument &document, FbdNetwork &network, const QString &text = kPlaceholder)
{
    InVariable variable;
    variable.expression = text;
    variable.connectionPointOut.emplace();
    return addTo(document, network, std::move(variable));
}

BlockVariable pin(const QString &name, bool input)
{
    BlockVariable v;
    v.formalParameter = name;
    if (input)
        v.connectionPointIn.emplace();
    else
        v.connectionPointOut.emplace();
    return v;
}

// The pin of a box that carries the data flow: after EN, when the box has one.
int firstDataInput(const Block &block)
{
    return !block.inputVariables.empty() && block.inputVariables.front().formalParameter.compare(QLatin1String("EN"), Qt::CaseInsensitive) == 0
            && block.inputVariables.size() > 1
        ? 1
        : 0;
}

int firstDataOutput(const Block &block)
{
    return !block.outputVariables.empty() && block.outputVariables.front().formalParameter.compare(QLatin1String("ENO"), Qt::CaseInsensitive) == 0
            && block.outputVariables.size() > 1
        ? 1
        : 0;
}

// A new box with "???" on every input but `wired` (which the caller connects).
quint64 newBox(FbdDocument &document, FbdNetwork &network, const BoxSpec &spec, int *dataInput, int *dataOutput)
{
    const Block block = blockFromSpec(spec);
    *dataInput = firstDataInput(block);
    *dataOutput = block.outputVariables.empty() ? -1 : firstDataOutput(block);
    const int inputs = int(block.inputVariables.size() + block.inOutVariables.size());
    const quint64 id = addTo(document, network, block);
    for (int p = 0; p < inputs; ++p)
        if (p != *dataInput)
            connectInput(document, id, p, {newVariable(document, network), 0});
    return id;
}

quint64 rootOf(const FbdDocument &document, const FbdNetwork &network)
{
    std::vector<quint64> read;
    for (quint64 id : network.members) {
        const Element *e = document.element(id);
        if (!e || !isNode(*e))
            continue;
        for (int pin = 0; pin < inputCount(*e); ++pin)
            if (const auto source = sourceOf(document, id, pin))
                read.push_back(source->element);
    }
    for (quint64 id : network.members) {
        const Element *e = document.element(id);
        if (e && isNode(*e) && std::ranges::find(read, id) == read.end())
            return id;
    }
    return 0;
}

void refreshRoot(FbdDocument &document, FbdNetwork &network)
{
    if (!network.freehand)
        network.root = rootOf(document, network);
}

// Text on a variable means the place it stands for: the input it feeds, or its output when it
// is the network's root; text on an assignment, jump or return means its crossing; an instance
// name means its box.
FbdCursor normalized(const FbdDocument &document, const FbdCursor &cursor)
{
    if (cursor.kind != Kind::Text)
        return cursor;
    const Element *e = document.element(cursor.element);
    if (!e)
        return cursor;
    if (isSink(*e))
        return FbdCursor::at(Kind::Crossing, cursor.network, cursor.element);
    if (std::holds_alternative<Block>(*e))
        return FbdCursor::at(Kind::Box, cursor.network, cursor.element);
    if (std::holds_alternative<InVariable>(*e) && cursor.network >= 0 && cursor.network < int(document.networks.size())) {
        const Readers readers = readersOf(document, document.networks[std::size_t(cursor.network)], {cursor.element, 0});
        if (!readers.nodes.empty())
            return FbdCursor::at(Kind::Input, cursor.network, readers.nodes.front().first, readers.nodes.front().second);
        return FbdCursor::at(Kind::Output, cursor.network, cursor.element, 0);
    }
    return cursor;
}

// The output a new sink or operator hangs on at the cursor, and the sink it goes before (0: last).
struct Attach {
    Port output;
    quint64 before = 0;
};

std::optional<Attach> attachPoint(FbdDocument &document, const FbdCursor &at, QString *error)
{
    FbdNetwork &network = document.networks[std::size_t(at.network)];
    switch (at.kind) {
    case Kind::Input:
        if (const auto source = sourceOf(document, at.element, at.pin))
            return Attach {*source, 0};
        *error = QCoreApplication::translate("iec::editors::fbd::FbdEdits", "Nothing is wired to this input yet.");
        return std::nullopt;
    case Kind::Output:
        return Attach {{at.element, at.pin}, 0};
    case Kind::Crossing:
        if (const auto source = sourceOf(document, at.element, 0))
            return Attach {*source, at.element};
        *error = QCoreApplication::translate("iec::editors::fbd::FbdEdits", "Nothing is wired to this element yet.");
        return std::nullopt;
    case Kind::Box: {
        const auto *block = std::get_if<Block>(document.element(at.element));
        if (block && !block->outputVariables.empty())
            return Attach {{at.element, firstDataOutput(*block)}, 0};
        *error = QCoreApplication::translate("iec::editors::fbd::FbdEdits", "This box has no output.");
        return std::nullopt;
    }
    case Kind::End:
    case Kind::Network:
    case Kind::Text:
        break;
    }
    refreshRoot(document, network);
    if (!network.root)
        network.root = newVariable(document, network);
    const auto *block = std::get_if<Block>(document.element(network.root));
    if (block && block->outputVariables.empty()) {
        *error = QCoreApplication::translate("iec::editors::fbd::FbdEdits", "The last box of this network has no output.");
        return std::nullopt;
    }
    return Attach {{network.root, block ? firstDataOutput(*block) : 0}, 0};
}

// Puts `id` into the network's members just before `before` (so it is drawn above it).
void moveBefore(FbdNetwork &network, quint64 id, quint64 before)
{
    if (!before)
        return;
    std::erase(network.members, id);
    const auto at = std::ranges::find(network.members, before);
    network.members.insert(at, id);
}

FbdEditResult insertSink(FbdDocument &document, const FbdCursor &cursor, Element sink)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    const FbdCursor at = normalized(document, cursor);
    QString error;
    const std::optional<Attach> attach = attachPoint(document, at, &error);
    if (!attach)
        return {error, {}};
    FbdNetwork &network = document.networks[std::size_t(at.network)];
    const quint64 id = addTo(document, network, std::move(sink));
    connectInput(document, id, 0, attach->output);
    moveBefore(network, id, attach->before);
    refreshRoot(document, network);
    return {{}, FbdCursor::at(Kind::Text, at.network, id)};
}

Block *blockAt(FbdDocument &document, quint64 id)
{
    Element *e = document.element(id);
    return e ? std::get_if<Block>(e) : nullptr;
}

// The number of an extensible input ("IN3" → 3; "In1" → 1), -1 for another name.
int inputNumber(const QString &name)
{
    if (!name.startsWith(QLatin1String("IN"), Qt::CaseInsensitive))
        return -1;
    bool ok = false;
    const int number = name.mid(2).toInt(&ok);
    return ok ? number : -1;
}

void removeBranch(FbdDocument &document, FbdNetwork &network, quint64 node)
{
    document.remove(branchOf(document, network, node));
}

} // namespace detail

using namespace detail;

// ---- networks

FbdEditResult insertNetwork(FbdDocument &document, const FbdCursor &cursor, bool after)
{
    const int count = int(document.networks.size());
    const int at = count == 0 ? 0 : std::clamp(cursor.network + (after ? 1 : 0), 0, count);
    document.networks.insert(document.networks.begin() + at, FbdNetwork {});
    FbdNetwork &network = document.networks[std::size_t(at)];
    const quint64 input = newVariable(document, network);
    OutVariable output;
    output.expression = kPlaceholder;
    output.connectionPointIn.emplace();
    const quint64 assignment = addTo(document, network, std::move(output));
    connectInput(document, assignment, 0, {input, 0});
    network.root = input;
    return {{}, FbdCursor::at(Kind::Text, at, input)};
}

FbdEditResult setNetworkLabel(FbdDocument &document, int index, const QString &text)
{
    if (const auto problem = checkNetwork(document, index, false))
        return {*problem, {}};
    FbdNetwork &network = document.networks[std::size_t(index)];
    const QString label = text.trimmed();
    if (label.isEmpty()) {
        if (network.label)
            document.remove({network.label});
        return {{}, FbdCursor::atNetwork(index)};
    }
    if (Element *e = network.label ? document.element(network.label) : nullptr) {
        std::get<Label>(*e).label = label;
    } else {
        Label element;
        element.label = label;
        network.label = addTo(document, network, std::move(element));
    }
    return {{}, FbdCursor::atNetwork(index)};
}

FbdEditResult setNetworkComment(FbdDocument &document, int index, const QString &text)
{
    if (const auto problem = checkNetwork(document, index, false))
        return {*problem, {}};
    FbdNetwork &network = document.networks[std::size_t(index)];
    if (text.trimmed().isEmpty()) {
        if (network.comment)
            document.remove({network.comment});
        return {{}, FbdCursor::atNetwork(index)};
    }
    if (Element *e = network.comment ? document.element(network.comment) : nullptr) {
        std::get<Comment>(*e).content.text = text;
    } else {
        Comment element;
        element.content.text = text;
        network.comment = addTo(document, network, std::move(element));
    }
    return {{}, FbdCursor::atNetwork(index)};
}

// ---- inputs and outputs

FbdEditResult insertInput(FbdDocument &document, const FbdCursor &cursor)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    const FbdCursor at = normalized(document, cursor);
    Block *block = (at.kind == Kind::Input || at.kind == Kind::Box) ? blockAt(document, at.element) : nullptr;
    if (!block)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Select a box or one of its inputs first."));
    if (!isExtensible(block->typeName))
        return {QCoreApplication::translate("iec::editors::fbd::FbdEdits", "%1 has a fixed number of inputs.").arg(block->typeName), {}};
    const int inputs = int(block->inputVariables.size());
    // Never in front of EN: it stays the first input.
    const int insertAt = at.kind == Kind::Input ? std::clamp(at.pin, firstDataInput(*block), inputs) : inputs;
    // The inputs are numbered again in their order, in the style of the first (IN1 or In1; MUX
    // counts from IN0 after K).
    BlockVariable added = pin(QString(), true);
    block->inputVariables.insert(block->inputVariables.begin() + insertAt, std::move(added));
    QString prefix = QStringLiteral("IN");
    int number = -1;
    for (const BlockVariable &v : block->inputVariables)
        if (inputNumber(v.formalParameter) >= 0) {
            prefix = v.formalParameter.left(2);
            number = inputNumber(v.formalParameter);
            break;
        }
    if (number < 0)
        number = 1;
    for (BlockVariable &v : block->inputVariables)
        if (inputNumber(v.formalParameter) >= 0 || v.formalParameter.isEmpty())
            v.formalParameter = prefix + QString::number(number++);
    const quint64 box = at.element;
    FbdNetwork &network = document.networks[std::size_t(at.network)];
    connectInput(document, box, insertAt, {newVariable(document, network), 0});
    return {{}, FbdCursor::at(Kind::Input, at.network, box, insertAt)};
}

FbdEditResult insertOutput(FbdDocument &document, const FbdCursor &cursor)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    FbdCursor at = normalized(document, cursor);
    OutVariable output;
    output.expression = kPlaceholder;
    output.connectionPointIn.emplace();
    if (at.kind == Kind::Crossing) {
        // Next to the selected assignment: below it, on the same line.
        FbdEditResult result = insertSink(document, at, std::move(output));
        if (result.ok()) {
            FbdNetwork &network = document.networks[std::size_t(at.network)];
            std::erase(network.members, result.cursor.element);
            const auto it = std::ranges::find(network.members, at.element);
            network.members.insert(it == network.members.end() ? it : it + 1, result.cursor.element);
        }
        return result;
    }
    return insertSink(document, at, std::move(output));
}

// ---- operators

FbdEditResult insertOperator(FbdDocument &document, const FbdCursor &cursor, const BoxSpec &spec)
{
    if (const auto problem = checkNetwork(document, cursor.network, true))
        return {*problem, {}};
    const FbdCursor at = normalized(document, cursor);
    FbdNetwork &network = document.networks[std::size_t(at.network)];
    int dataInput = 0;
    int dataOutput = 0;
    if (at.kind == Kind::Box) {
        // Replaces the box in place: same element, so every wire stays where it can.
        Block *old = blockAt(document, at.element);
        if (!old)
            return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Select a box first."));
        Block fresh = blockFromSpec(spec);
        // An extensible operator takes every branch the old box had (ADD with four inputs → MUL
        // with four).
        if (isExtensible(spec.typeName) && !fresh.inputVariables.empty()) {
            const QString last = fresh.inputVariables.back().formalParameter;
            const QString prefix = inputNumber(last) >= 0 ? last.left(2) : QStringLiteral("IN");
            int number = std::max(inputNumber(last), 0) + 1;
            while (fresh.inputVariables.size() < old->inputVariables.size())
                fresh.inputVariables.push_back(pin(prefix + QString::number(number++), true));
        }
        Block replaced = *old;
        replaced.typeName = fresh.typeName;
        replaced.instanceName = spec.functionBlock ? std::optional<QString>(old->instanceName.value_or(kPlaceholder)) : std::nullopt;
        const int oldInputs = int(old->inputVariables.size());
        const int newInputs = int(fresh.inputVariables.size());
        std::vector<quint64> dropped;
        for (int p = newInputs; p < oldInputs; ++p)
            if (const auto source = sourceOf(document, at.element, p))
                dropped.push_back(source->element);
        const std::vector<Port> oldOutputs = [&] {
            std::vector<Port> ports;
            for (int o = 0; o < int(old->outputVariables.size()); ++o)
                ports.push_back({at.element, o});
            return ports;
        }();
        const Readers before = [&] {
            Readers all;
            for (const Port &port : oldOutputs) {
                Readers r = readersOf(document, network, port);
                all.nodes.insert(all.nodes.end(), r.nodes.begin(), r.nodes.end());
                all.sinks.insert(all.sinks.end(), r.sinks.begin(), r.sinks.end());
            }
            return all;
        }();
        // Who reads which output, by index, before the names change.
        std::vector<std::pair<std::pair<quint64, int>, int>> nodeReaders;
        std::vector<std::pair<quint64, int>> sinkReaders;
        for (const auto &reader : before.nodes)
            if (const auto source = sourceOf(document, reader.first, reader.second))
                nodeReaders.push_back({reader, source->pin});
        for (quint64 sink : before.sinks)
            if (const auto source = sourceOf(document, sink, 0))
                sinkReaders.push_back({sink, source->pin});
        replaced.inputVariables.clear();
        for (int p = 0; p < newInputs; ++p) {
            BlockVariable v = fresh.inputVariables[std::size_t(p)];
            if (p < oldInputs) {
                const BlockVariable &was = old->inputVariables[std::size_t(p)];
                v.connectionPointIn = was.connectionPointIn;
                v.negated = was.negated;
                v.edge = was.edge;
            }
            replaced.inputVariables.push_back(std::move(v));
        }
        replaced.inOutVariables = fresh.inOutVariables;
        replaced.outputVariables = fresh.outputVariables;
        *old = std::move(replaced);
        for (quint64 branch : dropped)
            removeBranch(document, network, branch);
        const int outputs = int(fresh.outputVariables.size());
        for (const auto &[reader, pinIndex] : nodeReaders)
            connectInput(document, reader.first, reader.second, {at.element, std::clamp(pinIndex, 0, std::max(0, outputs - 1))});
        std::vector<quint64> lost;
        for (const auto &[sink, pinIndex] : sinkReaders) {
            if (pinIndex < outputs)
                connectInput(document, sink, 0, {at.element, pinIndex});
            else
                lost.push_back(sink);
        }
        document.remove(lost);
        for (int p = oldInputs; p < newInputs; ++p)
            connectInput(document, at.element, p, {newVariable(document, network), 0});
        refreshRoot(document, network);
        return {{}, FbdCursor::at(Kind::Box, at.network, at.element)};
    }
    if (at.kind == Kind::Input) {
        // Before the input: the new box's first input takes what fed it.
        const auto source = sourceOf(document, at.element, at.pin);
        const quint64 box = newBox(document, network, spec, &dataInput, &dataOutput);
        if (dataOutput < 0)
            return {QCoreApplication::translate("iec::editors::fbd::FbdEdits", "%1 has no output to feed the input with.").arg(spec.typeName), {}};
        if (source)
            connectInput(document, box, dataInput, *source);
        else
            connectInput(document, box, dataInput, {newVariable(document, network), 0});
        connectInput(document, at.element, at.pin, {box, dataOutput});
        refreshRoot(document, network);
        return {{}, FbdCursor::at(Kind::Box, at.network, box)};
    }
    if (at.kind == Kind::Crossing) {
        // Before the assignment, jump or return: only that one moves behind the new box.
        const auto source = sourceOf(document, at.element, 0);
        const quint64 box = newBox(document, network, spec, &dataInput, &dataOutput);
        if (dataOutput < 0)
            return {QCoreApplication::translate("iec::editors::fbd::FbdEdits", "%1 has no output to feed the assignment with.").arg(spec.typeName), {}};
        connectInput(document, box, dataInput, source ? *source : Port {newVariable(document, network), 0});
        connectInput(document, at.element, 0, {box, dataOutput});
        refreshRoot(document, network);
        return {{}, FbdCursor::at(Kind::Box, at.network, box)};
    }
    // After an output, or at the end of the network: the new box takes over what the output fed.
    QString error;
    const std::optional<Attach> attach = attachPoint(document, at.kind == Kind::Output ? at : FbdCursor::at(Kind::End, at.network), &error);
    if (!attach)
        return {error, {}};
    const Readers readers = readersOf(document, network, attach->output);
    const quint64 box = newBox(document, network, spec, &dataInput, &dataOutput);
    connectInput(document, box, dataInput, attach->output);
    if (dataOutput >= 0) {
        for (const auto &[target, pinIndex] : readers.nodes)
            connectInput(document, target, pinIndex, {box, dataOutput});
        for (quint64 sink : readers.sinks)
            connectInput(document, sink, 0, {box, dataOutput});
    } else if (!readers.nodes.empty() || !readers.sinks.empty()) {
        document.remove({box});
        return {QCoreApplication::translate("iec::editors::fbd::FbdEdits", "%1 has no output to pass the value on.").arg(spec.typeName), {}};
    }
    refreshRoot(document, network);
    return {{}, FbdCursor::at(Kind::Box, at.network, box)};
}

// ---- assignments, jumps, returns

FbdEditResult insertAssignment(FbdDocument &document, const FbdCursor &cursor)
{
    OutVariable output;
    output.expression = kPlaceholder;
    output.connectionPointIn.emplace();
    return insertSink(document, cursor, std::move(output));
}

FbdEditResult insertJump(FbdDocument &document, const FbdCursor &cursor, const QString &label)
{
    Jump jump;
    jump.label = label.trimmed().isEmpty() ? kPlaceholder : label.trimmed();
    jump.connectionPointIn.emplace();
    return insertSink(document, cursor, std::move(jump));
}

FbdEditResult insertReturn(FbdDocument &document, const FbdCursor &cursor)
{
    Return ret;
    ret.connectionPointIn.emplace();
    FbdEditResult result = insertSink(document, cursor, std::move(ret));
    if (result.ok())
        result.cursor.kind = Kind::Crossing; // a return has no text
    return result;
}

// ---- properties

FbdEditResult toggleNegation(FbdDocument &document, const FbdCursor &cursor)
{
    if (const auto problem = checkNetwork(document, cursor.network, false))
        return {*problem, {}};
    const FbdCursor at = normalized(document, cursor);
    Element *e = document.element(at.element);
    if (!e)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Select an input, an output, an assignment, a jump or a return first."));
    if (at.kind == Kind::Input) {
        if (Block *block = std::get_if<Block>(e); block && at.pin < int(block->inputVariables.size())) {
            auto &v = block->inputVariables[std::size_t(at.pin)];
            v.negated = !v.negated;
            return {{}, at};
        }
    }
    if (at.kind == Kind::Output) {
        if (Block *block = std::get_if<Block>(e); block && at.pin < int(block->outputVariables.size())) {
            auto &v = block->outputVariables[std::size_t(at.pin)];
            v.negated = !v.negated;
            return {{}, at};
        }
        if (auto *in = std::get_if<InVariable>(e)) {
            in->negated = !in->negated;
            return {{}, at};
        }
    }
    if (at.kind == Kind::Crossing) {
        if (auto *out = std::get_if<OutVariable>(e)) {
            out->negated = !out->negated;
            return {{}, cursor};
        }
        // A jump or return has no negation of its own in PLCopen: the output feeding it is
        // negated, when nothing else reads that output.
        const auto source = sourceOf(document, at.element, 0);
        Element *from = source ? document.element(source->element) : nullptr;
        const Readers readers = readersOf(document, document.networks[std::size_t(at.network)], source.value_or(Port {}));
        if (!from || readers.nodes.size() + readers.sinks.size() != 1)
            return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "The value in front of this jump or return goes elsewhere too: negate the output that feeds it, or insert a NOT."));
        if (Block *block = std::get_if<Block>(from); block && source->pin < int(block->outputVariables.size())) {
            auto &v = block->outputVariables[std::size_t(source->pin)];
            v.negated = !v.negated;
            return {{}, cursor};
        }
        if (auto *in = std::get_if<InVariable>(from)) {
            in->negated = !in->negated;
            return {{}, cursor};
        }
    }
    return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Select an input, an output, an assignment, a jump or a return first."));
}

FbdEditResult cycleSetReset(FbdDocument &document, const FbdCursor &cursor)
{
    if (const auto problem = checkNetwork(document, cursor.network, false))
        return {*problem, {}};
    FbdCursor at = normalized(document, cursor);
    quint64 target = at.kind == Kind::Crossing ? at.element : 0;
    if (at.kind == Kind::Output) {
        const Readers readers = readersOf(document, document.networks[std::size_t(at.network)], {at.element, at.pin});
        std::vector<quint64> assignments;
        for (quint64 sink : readers.sinks)
            if (std::holds_alternative<OutVariable>(*document.element(sink)))
                assignments.push_back(sink);
        if (assignments.size() == 1)
            target = assignments.front();
    }
    auto *out = target ? std::get_if<OutVariable>(document.element(target)) : nullptr;
    if (!out)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Select an assignment (an output variable) first."));
    out->storage = out->storage == StorageModifier::None ? StorageModifier::Set
        : out->storage == StorageModifier::Set          ? StorageModifier::Reset
                                                        : StorageModifier::None;
    return {{}, cursor};
}

FbdEditResult cycleEdge(FbdDocument &document, const FbdCursor &cursor)
{
    if (const auto problem = checkNetwork(document, cursor.network, false))
        return {*problem, {}};
    const FbdCursor at = normalized(document, cursor);
    Block *block = at.kind == Kind::Input ? blockAt(document, at.element) : nullptr;
    if (!block || at.pin >= int(block->inputVariables.size()))
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Select an input of a box first (edge detection works on BOOL inputs)."));
    auto &v = block->inputVariables[std::size_t(at.pin)];
    v.edge = v.edge == EdgeModifier::None ? EdgeModifier::Rising : v.edge == EdgeModifier::Rising ? EdgeModifier::Falling : EdgeModifier::None;
    return {{}, cursor};
}

// ---- texts

QString elementText(const FbdDocument &document, quint64 localId)
{
    const Element *e = document.element(localId);
    if (!e)
        return {};
    if (const auto *in = std::get_if<InVariable>(e))
        return in->expression;
    if (const auto *out = std::get_if<OutVariable>(e))
        return out->expression;
    if (const auto *inOut = std::get_if<InOutVariable>(e))
        return inOut->expression;
    if (const auto *block = std::get_if<Block>(e))
        return block->instanceName.value_or(QString());
    if (const auto *jump = std::get_if<Jump>(e))
        return jump->label;
    if (const auto *label = std::get_if<Label>(e))
        return label->label;
    return {};
}

FbdEditResult setElementText(FbdDocument &document, quint64 localId, const QString &text)
{
    Element *e = document.element(localId);
    const int network = document.networkOf(localId);
    const QString value = text.trimmed();
    if (!e || network < 0)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "There is no such element."));
    if (value.isEmpty())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Type a name or a value."));
    if (auto *in = std::get_if<InVariable>(e))
        in->expression = value;
    else if (auto *out = std::get_if<OutVariable>(e))
        out->expression = value;
    else if (auto *inOut = std::get_if<InOutVariable>(e))
        inOut->expression = value;
    else if (auto *block = std::get_if<Block>(e); block && block->instanceName)
        block->instanceName = value;
    else if (auto *jump = std::get_if<Jump>(e))
        jump->label = value;
    else if (auto *label = std::get_if<Label>(e))
        label->label = value;
    else
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "This element has no name to type."));
    return {{}, FbdCursor::at(Kind::Text, network, localId)};
}

// ---- delete

FbdEditResult deleteAtCursor(FbdDocument &document, const FbdCursor &cursor)
{
    if (const auto problem = checkNetwork(document, cursor.network, false))
        return {*problem, {}};
    FbdNetwork &network = document.networks[std::size_t(cursor.network)];
    if (cursor.kind == Kind::Network) {
        document.remove(network.members);
        document.networks.erase(document.networks.begin() + cursor.network);
        return {{}, FbdCursor::atNetwork(std::max(0, std::min(cursor.network, int(document.networks.size()) - 1)))};
    }
    const Element *e = document.element(cursor.element);
    if (network.freehand) {
        if (!e || cursor.kind == Kind::End)
            return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Select an element of the network first."));
        document.remove({cursor.element});
        return {{}, FbdCursor::atNetwork(cursor.network)};
    }
    if (cursor.kind == Kind::Text && e && std::holds_alternative<InVariable>(*e)) {
        std::get<InVariable>(*document.element(cursor.element)).expression = kPlaceholder;
        return {{}, cursor};
    }
    const FbdCursor at = normalized(document, cursor);
    switch (at.kind) {
    case Kind::Crossing:
        document.remove({at.element});
        break;
    case Kind::Output: {
        const Readers readers = readersOf(document, network, {at.element, at.pin});
        if (readers.sinks.empty())
            return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "There is no assignment on this output to delete."));
        document.remove(readers.sinks);
        break;
    }
    case Kind::Input: {
        Block *block = blockAt(document, at.element);
        if (!block)
            return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Select an input of a box first."));
        if (const auto source = sourceOf(document, at.element, at.pin))
            removeBranch(document, network, source->element);
        block = blockAt(document, at.element);
        if (isExtensible(block->typeName) && block->inputVariables.size() > 2 && at.pin < int(block->inputVariables.size())) {
            block->inputVariables.erase(block->inputVariables.begin() + at.pin);
            refreshRoot(document, network);
            return {{}, FbdCursor::at(Kind::Box, at.network, at.element)};
        }
        connectInput(document, at.element, at.pin, {newVariable(document, network), 0});
        break;
    }
    case Kind::Box: {
        // The box and everything that feeds it; what it fed reads "???" now.
        const Element *box = document.element(at.element);
        std::vector<std::pair<std::pair<quint64, int>, bool>> readers; // (target, pin), is a sink
        for (int out = 0; out < outputCount(*box); ++out) {
            const Readers r = readersOf(document, network, {at.element, out});
            for (const auto &node : r.nodes)
                readers.push_back({node, false});
            for (quint64 sink : r.sinks)
                readers.push_back({{sink, 0}, true});
        }
        removeBranch(document, network, at.element);
        quint64 placeholder = 0;
        for (const auto &[reader, sink] : readers) {
            if (!document.element(reader.first))
                continue;
            if (!placeholder || !sink)
                placeholder = newVariable(document, network);
            connectInput(document, reader.first, reader.second, {placeholder, 0});
        }
        break;
    }
    case Kind::End:
    case Kind::Network:
    case Kind::Text:
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "Select what to delete first: an element, an input, an output or a network."));
    }
    refreshRoot(document, network);
    if (!network.root && std::ranges::none_of(network.members, [&](quint64 id) { return id == network.label || id == network.comment ? false : true; })) {
        // Nothing but a label or comment left: the network goes.
        document.remove(network.members);
        document.networks.erase(document.networks.begin() + at.network);
        return {{}, FbdCursor::atNetwork(std::max(0, std::min(at.network, int(document.networks.size()) - 1)))};
    }
    return {{}, FbdCursor::atNetwork(at.network)};
}

} // namespace iec::editors::fbd
