#include "editors/ld/ldnetwork.h"

#include <algorithm>

namespace iec::editors::ld {

using namespace model;

void LadderDocument::remove(const std::vector<quint64> &localIds)
{
    removeElements(localIds);
    for (LdNetwork &network : networks)
        std::erase_if(network.members, [&](quint64 id) { return std::ranges::find(localIds, id) != localIds.end(); });
    for (quint64 id : localIds)
        boxPins.erase(id);
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
