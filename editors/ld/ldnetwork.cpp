#include "editors/ld/ldnetwork.h"

#include <algorithm>

namespace iec::editors::ld {

using namespace model;

const Element *LadderDocument::element(quint64 localId) const
{
    const int at = indexOf(localId);
    return at < 0 ? nullptr : &elements[std::size_t(at)];
}

Element *LadderDocument::element(quint64 localId)
{
    const int at = indexOf(localId);
    return at < 0 ? nullptr : &elements[std::size_t(at)];
}

int LadderDocument::indexOf(quint64 localId) const
{
    const auto it = m_index.constFind(localId);
    return it == m_index.cend() ? -1 : int(it.value());
}

quint64 LadderDocument::allocateId()
{
    return ++idFloor; // reindex() keeps the floor at or above every id the document holds
}

quint64 LadderDocument::add(Element element, int index)
{
    const quint64 id = allocateId();
    header(element).localId = id;
    if (index < 0 || index > int(elements.size()))
        index = int(elements.size());
    elements.insert(elements.begin() + index, std::move(element));
    reindexFrom(std::size_t(index));
    return id;
}

void LadderDocument::remove(const std::vector<quint64> &localIds)
{
    const auto removed = [&](const Element &e) { return std::ranges::find(localIds, header(e).localId) != localIds.end(); };
    const auto first = std::ranges::find_if(elements, removed);
    const std::size_t firstIndex = std::size_t(first - elements.begin());
    for (quint64 id : localIds)
        m_index.remove(id);
    std::erase_if(elements, removed);
    // Wires from the removed elements go with them.
    for (Element &e : elements) {
        for (ConnectionPointIn *point : inputPoints(e))
            std::erase_if(point->connections,
                [&](const Connection &c) { return std::ranges::find(localIds, c.refLocalId) != localIds.end(); });
    }
    for (LdNetwork &network : networks)
        std::erase_if(network.members, [&](quint64 id) { return std::ranges::find(localIds, id) != localIds.end(); });
    for (quint64 id : localIds)
        boxPins.erase(id);
    reindexFrom(firstIndex);
}

void LadderDocument::moveElement(int from, int to)
{
    if (from == to || from < 0 || to < 0 || from >= int(elements.size()) || to >= int(elements.size()))
        return;
    Element moved = std::move(elements[std::size_t(from)]);
    elements.erase(elements.begin() + from);
    elements.insert(elements.begin() + to, std::move(moved));
    reindexFrom(std::size_t(std::min(from, to)), std::size_t(std::max(from, to)) + 1);
}

int LadderDocument::networkOf(quint64 localId) const
{
    for (std::size_t n = 0; n < networks.size(); ++n) {
        if (std::ranges::find(networks[n].members, localId) != networks[n].members.end())
            return int(n);
    }
    return -1;
}

RungPins LadderDocument::pinsOf(quint64 boxId) const
{
    const auto it = boxPins.find(boxId);
    return it == boxPins.end() ? RungPins {} : it->second;
}

void LadderDocument::reindex()
{
    m_index.clear();
    m_index.reserve(qsizetype(elements.size()));
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const quint64 id = header(elements[i]).localId;
        if (!m_index.contains(id)) // a hostile file's second element with one id stays unreachable
            m_index.insert(id, i);
        idFloor = std::max(idFloor, id);
    }
}

void LadderDocument::reindexFrom(std::size_t first, std::size_t last)
{
    last = std::min(last, elements.size());
    for (std::size_t i = first; i < last; ++i) {
        const quint64 id = header(elements[i]).localId;
        m_index.insert(id, i);
        idFloor = std::max(idFloor, id);
    }
}

RungRole rungRole(const Element &element)
{
    if (std::holds_alternative<Contact>(element))
        return RungRole::Contact;
    if (std::holds_alternative<Coil>(element))
        return RungRole::Coil;
    if (std::holds_alternative<Block>(element))
        return RungRole::Box;
    if (std::holds_alternative<Jump>(element))
        return RungRole::Jump;
    if (std::holds_alternative<Return>(element))
        return RungRole::Return;
    if (std::holds_alternative<OutVariable>(element))
        return RungRole::Assignment;
    return RungRole::Other;
}

bool isOutput(const Element &element)
{
    const RungRole role = rungRole(element);
    return role == RungRole::Coil || role == RungRole::Jump || role == RungRole::Return || role == RungRole::Assignment;
}

namespace {

model::AddData *addDataOf(Element &element)
{
    if (auto *left = std::get_if<LeftPowerRail>(&element))
        return &left->addData;
    if (auto *right = std::get_if<RightPowerRail>(&element))
        return &right->addData;
    return nullptr;
}

} // namespace

bool isNetworkRail(const Element &element)
{
    const model::AddData *data = addDataOf(const_cast<Element &>(element));
    return data && std::ranges::any_of(*data, [](const AddDataEntry &d) { return d.name == kNetworkRailMarker; });
}

void markNetworkRail(Element &element)
{
    if (model::AddData *data = addDataOf(element); data && !isNetworkRail(element))
        data->push_back(AddDataEntry {kNetworkRailMarker, QStringLiteral("discard"), QStringLiteral("<networkRail/>")});
}

void collectElements(const RungNode &node, std::vector<quint64> &out)
{
    if (node.isElement()) {
        out.push_back(node.localId);
        return;
    }
    for (const RungNode &child : node.children)
        collectElements(child, out);
}

std::vector<quint64> rungElements(const RungNode &node)
{
    std::vector<quint64> ids;
    collectElements(node, ids);
    return ids;
}

} // namespace iec::editors::ld
