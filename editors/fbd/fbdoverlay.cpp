#include "editors/fbd/fbdoverlay.h"

#include "editors/common/blockitems.h"
#include "editors/common/diagramonline.h"
#include "editors/common/diagramscene.h"
#include "editors/fbd/fbdscene.h"
#include "editors/fbd/fbdvalues.h"
#include "editors/text/onlinevalues.h"
#include "interpreter/runtime/snapshot.h"

namespace iec::editors::fbd {

using namespace model;

namespace {

QString pathOf(const Element &e)
{
    if (const auto *in = std::get_if<InVariable>(&e))
        return in->expression;
    if (const auto *out = std::get_if<OutVariable>(&e))
        return out->expression;
    if (const auto *inOut = std::get_if<InOutVariable>(&e))
        return inOut->expression;
    return {};
}

} // namespace

FbdOverlayMapper::FbdOverlayMapper(const FbdPolicy &policy)
    : m_policy(policy)
{
}

QString FbdOverlayMapper::variableName(quint64 localId, const QString &instance) const
{
    const Element *e = m_policy.document().element(localId);
    const QString path = e ? pathOf(*e).trimmed() : QString();
    if (!isVariablePath(path) || path.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0
        || path.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0)
        return {};
    return onlineName(instance, path);
}

QStringList FbdOverlayMapper::names(const DiagramScene &, const QString &instance) const
{
    QStringList names;
    for (const Element &e : m_policy.document().elements) {
        if (const QString name = variableName(header(e).localId, instance); !name.isEmpty())
            names << name;
        if (const auto *block = std::get_if<Block>(&e))
            names += instancePinNames(*block, instance).values();
    }
    names.removeDuplicates();
    return names;
}

void FbdOverlayMapper::apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance)
{
    m_values = snapshot.values;
    const std::vector<FbdGeometry> &layout = m_policy.layout();
    const auto [first, last] = visibleBands(scene, layout.size(), [&](std::size_t i) { return layout[i].top; },
        [&](std::size_t i) { return layout[i].top + layout[i].height; });
    for (std::size_t n = first; n < last && n < m_policy.networkItems().size(); ++n)
        applyToNetwork(scene, n, snapshot, instance);
}

void FbdOverlayMapper::applyToNetwork(DiagramScene &scene, std::size_t index, const interp::RuntimeSnapshot &snapshot, const QString &instance)
{
    const FbdDocument &document = m_policy.document();
    const FbdNetwork &network = document.networks[index];
    const auto values = networkValues(
        document, network,
        [&](quint64 id, const QString &path) {
            const QString name = variableName(id, instance);
            return name.isEmpty() ? path.trimmed() : snapshot.value(name);
        },
        [&](quint64 box, const QString &pin) {
            const auto *block = std::get_if<Block>(document.element(box));
            return block ? snapshot.value(instancePinNames(*block, instance).value(pin.toUpper())) : QString();
        });
    const auto valueAt = [&](quint64 id, int pin) {
        const auto it = values.find({id, pin});
        return it == values.end() ? QString() : it->second;
    };
    const FbdPolicy::NetworkItems &items = m_policy.networkItems()[index];
    for (QGraphicsItem *item : items.wires)
        if (auto *wire = qgraphicsitem_cast<WireItem *>(item)) {
            // The wire's output: a box's formal output is not on the item, so look it up.
            bool powered = false;
            for (const FbdWire &run : m_policy.layout()[index].wires)
                if (run.source == wire->source() && run.target == wire->target() && run.points == wire->points())
                    powered = isTrueLiteral(valueAt(run.source, run.sourcePin));
            wire->setPowered(powered);
        }
    for (quint64 id : items.elements) {
        DiagramItem *item = scene.itemFor(id);
        const Element *e = document.element(id);
        if (!item || !e)
            continue;
        if (auto *box = dynamic_cast<BoxItem *>(item)) {
            const auto &block = std::get<Block>(*e);
            // Values at the outputs only: an input shows the value of what feeds it already (a
            // variable its own, a box its output), and an output whose assignment shows the value
            // leaves it to the assignment, so each value stands once on the drawing.
            // An inner box's free outputs have the next branch's wires beside them: only the last
            // box shows those.
            QHash<QString, QString> pins;
            for (int out = 0; out < int(block.outputVariables.size()); ++out) {
                const Readers readers = readersOf(document, network, {id, out});
                const bool room = id == network.root || network.freehand || !readers.nodes.empty();
                if (const QString v = valueAt(id, out); !v.isEmpty() && readers.sinks.empty() && room)
                    pins.insert(block.outputVariables[std::size_t(out)].formalParameter.toUpper(), v);
            }
            box->setPinValues(pins);
        } else if (auto *element = dynamic_cast<ElementItem *>(item)) {
            const QString name = variableName(id, instance);
            element->setForced(!name.isEmpty() && snapshot.isForced(name));
            if (dynamic_cast<VariableItem *>(element)) {
                const QString v = name.isEmpty() ? QString() : snapshot.value(name);
                element->setOnlineText(v);
                element->setActive(isTrueLiteral(v));
            } else if (const auto source = sourceOf(document, id, 0)) {
                element->setActive(isTrueLiteral(valueAt(source->element, source->pin))); // a jump or return taken
            }
        }
    }
}

void FbdOverlayMapper::clear(DiagramScene &scene)
{
    m_values.clear();
    for (QGraphicsItem *item : scene.items()) {
        if (auto *wire = qgraphicsitem_cast<WireItem *>(item))
            wire->setPowered(false);
        else if (auto *box = dynamic_cast<BoxItem *>(item))
            box->setPinValues({});
        if (auto *element = dynamic_cast<ElementItem *>(item)) {
            element->setActive(false);
            element->setForced(false);
            element->setOnlineText({});
        }
    }
}

} // namespace iec::editors::fbd
