#include "editors/cfc/cfcoverlay.h"

#include "editors/cfc/cfcscene.h"
#include "editors/common/blockitems.h"
#include "editors/common/diagramonline.h"
#include "editors/fbd/fbddocument.h"
#include "editors/fbd/fbdvalues.h"
#include "editors/text/onlinevalues.h"
#include "interpreter/runtime/snapshot.h"

namespace iec::editors::cfc {

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

const Element *elementOf(const DiagramScene &scene, quint64 localId)
{
    if (const std::vector<Element> *elements = scene.shownElements())
        for (const Element &e : *elements)
            if (header(e).localId == localId)
                return &e;
    return nullptr;
}

QString nameOf(const Element &e, const QString &instance)
{
    const QString path = pathOf(e).trimmed();
    if (!isVariablePath(path) || path.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0
        || path.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0)
        return {};
    return onlineName(instance, path);
}

} // namespace

CfcOverlayMapper::CfcOverlayMapper(const CfcPolicy &policy)
    : m_policy(policy)
{
}

QString CfcOverlayMapper::variableName(const DiagramScene &scene, quint64 localId, const QString &instance) const
{
    const Element *e = elementOf(scene, localId);
    return e ? nameOf(*e, instance) : QString();
}

QStringList CfcOverlayMapper::names(const DiagramScene &scene, const QString &instance) const
{
    QStringList names;
    if (const std::vector<Element> *elements = scene.shownElements()) {
        for (const Element &e : *elements) {
            if (const QString name = nameOf(e, instance); !name.isEmpty())
                names << name;
            if (const auto *block = std::get_if<Block>(&e))
                names += instancePinNames(*block, instance).values();
        }
    }
    names.removeDuplicates();
    return names;
}

void CfcOverlayMapper::apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance)
{
    m_values = snapshot.values;
    const std::vector<Element> *elements = scene.shownElements();
    if (!elements)
        return;
    // The whole chart as one freehand network of FBD's value computation.
    fbd::FbdDocument document;
    document.elements = *elements;
    document.reindex();
    fbd::FbdNetwork network;
    network.freehand = true;
    for (const Element &e : *elements)
        network.members.push_back(header(e).localId);
    const auto values = fbd::networkValues(
        document, network,
        [&](quint64 id, const QString &path) {
            const Element *e = document.element(id);
            const QString name = e ? nameOf(*e, instance) : QString();
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
    m_policy.forEachWire([&](const CfcWire &wire, WireItem &item) {
        const Element *source = document.element(wire.source);
        const int pin = source ? std::max(0, outputPinIndex(*source, wire.formalParameter)) : 0;
        item.setPowered(!wire.broken && isTrueLiteral(valueAt(wire.source, pin)));
    });
    for (const Element &e : *elements) {
        const quint64 id = header(e).localId;
        DiagramItem *item = scene.itemFor(id);
        if (auto *box = dynamic_cast<BoxItem *>(item)) {
            const auto &block = std::get<Block>(e);
            QHash<QString, QString> pins;
            for (int out = 0; out < int(block.outputVariables.size()); ++out)
                if (const QString v = valueAt(id, out); !v.isEmpty())
                    pins.insert(block.outputVariables[std::size_t(out)].formalParameter.toUpper(), v);
            box->setPinValues(pins);
        } else if (auto *element = dynamic_cast<ElementItem *>(item)) {
            const QString name = nameOf(e, instance);
            element->setForced(!name.isEmpty() && snapshot.isForced(name));
            if (dynamic_cast<VariableItem *>(element)) {
                const QString v = name.isEmpty() ? QString() : snapshot.value(name);
                element->setOnlineText(v);
                element->setActive(isTrueLiteral(v));
            }
        }
    }
}

void CfcOverlayMapper::clear(DiagramScene &scene)
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

} // namespace iec::editors::cfc
