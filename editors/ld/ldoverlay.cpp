#include "editors/ld/ldoverlay.h"

#include "editors/common/blockitems.h"
#include "editors/common/diagramonline.h"
#include "editors/common/diagramscene.h"
#include "editors/ld/ldscene.h"
#include "editors/text/onlinevalues.h"
#include "interpreter/runtime/snapshot.h"

#include <QGraphicsView>

#include <algorithm>

namespace iec::editors::ld {

using namespace model;

namespace {

QString pathOf(const Element &e)
{
    if (const auto *contact = std::get_if<Contact>(&e))
        return contact->variable;
    if (const auto *coil = std::get_if<Coil>(&e))
        return coil->variable;
    if (const auto *in = std::get_if<InVariable>(&e))
        return in->expression;
    if (const auto *out = std::get_if<OutVariable>(&e))
        return out->expression;
    return {};
}

} // namespace

LdOverlayMapper::LdOverlayMapper(const LdPolicy &policy)
    : m_policy(policy)
{
}

QString LdOverlayMapper::variableName(quint64 localId, const QString &instance) const
{
    const Element *e = m_policy.document().element(localId);
    const QString path = e ? pathOf(*e) : QString();
    return isVariablePath(path) ? onlineName(instance, path.trimmed()) : QString();
}

QStringList LdOverlayMapper::names(const DiagramScene &, const QString &instance) const
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

void LdOverlayMapper::apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance)
{
    // Edges show only when stepping one cycle at a time: then the last view is the cycle before.
    if (snapshot.cycle != m_lastCycle) {
        m_values.consecutive = snapshot.cycle == m_lastCycle + 1;
        m_values.before = std::move(m_values.now);
        m_values.now = snapshot.values;
        m_lastCycle = snapshot.cycle;
    }
    // Only what is on screen: a body of 1,000 networks shows a few of them, and the editor applies
    // the snapshot again when the view scrolls.
    const std::vector<NetworkGeometry> &layout = m_policy.layout();
    const auto [first, last] = visibleBands(scene, layout.size(), [&](std::size_t i) { return layout[i].top; },
        [&](std::size_t i) { return layout[i].top + layout[i].height; });
    for (std::size_t n = first; n < last && n < m_policy.networkItems().size(); ++n)
        applyToNetwork(scene, n, snapshot, instance);
}

void LdOverlayMapper::applyToNetwork(DiagramScene &scene, std::size_t index, const interp::RuntimeSnapshot &snapshot, const QString &instance)
{
    const LadderDocument &document = m_policy.document();
    const LdNetwork &network = document.networks[index];
    std::unordered_map<quint64, bool> wireSources; // element -> it passes power on
    if (!network.freehand) {
        const PowerFlow flow = evaluateRung(network.rung, [&](quint64 id, bool in) -> std::optional<bool> {
            const Element *e = document.element(id);
            if (const auto *contact = std::get_if<Contact>(e))
                return in && contactCloses(*contact, variableName(id, instance), m_values);
            if (std::holds_alternative<Coil>(*e))
                return in;
            if (const auto *block = std::get_if<Block>(e)) {
                const RungPins pins = document.pinsOf(id);
                if (pins.output < 0)
                    return std::nullopt;
                // A function block's rung output is its own (TON's Q); a function passes EN on.
                const QString pin = block->outputVariables[std::size_t(pins.output)].formalParameter;
                const QString name = instancePinNames(*block, instance).value(pin.toUpper());
                return name.isEmpty() ? in : isTrueLiteral(m_values.now.value(name));
            }
            return std::nullopt;
        });
        if (network.leftRail)
            wireSources[network.leftRail] = true;
        for (const auto &[id, out] : flow.out)
            wireSources[id] = out;
        for (const auto &[id, in] : flow.in) {
            DiagramItem *item = scene.itemFor(id);
            if (!item)
                continue;
            const Element *e = document.element(id);
            if (std::holds_alternative<Contact>(*e))
                item->setActive(contactCloses(std::get<Contact>(*e), variableName(id, instance), m_values));
            else if (std::holds_alternative<Coil>(*e))
                item->setActive(isTrueLiteral(m_values.now.value(variableName(id, instance))));
            else
                item->setActive(in);
        }
    }
    const LdPolicy::NetworkItems &items = m_policy.networkItems()[index];
    for (QGraphicsItem *item : items.wires) {
        if (auto *wire = qgraphicsitem_cast<WireItem *>(item)) {
            const auto it = wireSources.find(wire->source());
            wire->setPowered(it != wireSources.end() && it->second);
        }
    }
    for (quint64 id : items.elements) {
        DiagramItem *item = scene.itemFor(id);
        if (auto *box = dynamic_cast<BoxItem *>(item)) {
            QHash<QString, QString> values;
            const auto names = instancePinNames(std::get<Block>(box->element()), instance);
            for (auto it = names.begin(); it != names.end(); ++it)
                values.insert(it.key(), snapshot.value(it.value()));
            box->setPinValues(values);
        } else if (auto *element = dynamic_cast<ElementItem *>(item)) {
            const QString name = variableName(element->localId(), instance);
            element->setForced(!name.isEmpty() && snapshot.isForced(name));
            if (dynamic_cast<VariableItem *>(element))
                element->setOnlineText(name.isEmpty() ? QString() : snapshot.value(name));
        }
    }
}

void LdOverlayMapper::clear(DiagramScene &scene)
{
    m_values = {};
    m_lastCycle = -1;
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

} // namespace iec::editors::ld
