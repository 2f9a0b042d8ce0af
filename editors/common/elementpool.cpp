#include "editors/common/elementpool.h"

#include <algorithm>

namespace iec::editors {

using namespace model;

const Element *ElementPool::element(quint64 localId) const
{
    const int at = indexOf(localId);
    return at < 0 ? nullptr : &elements[std::size_t(at)];
}

Element *ElementPool::element(quint64 localId)
{
    const int at = indexOf(localId);
    return at < 0 ? nullptr : &elements[std::size_t(at)];
}

int ElementPool::indexOf(quint64 localId) const
{
    const auto it = m_index.constFind(localId);
    return it == m_index.cend() ? -1 : int(it.value());
}

quint64 ElementPool::allocateId()
{
    return ++idFloor; // reindex() keeps the floor at or above every id the pool holds
}

quint64 ElementPool::add(Element element, int index)
{
    const quint64 id = allocateId();
    header(element).localId = id;
    if (index < 0 || index > int(elements.size()))
        index = int(elements.size());
    elements.insert(elements.begin() + index, std::move(element));
    reindexFrom(std::size_t(index));
    return id;
}

void ElementPool::removeElements(const std::vector<quint64> &localIds)
{
    const auto listed = [&](quint64 id) { return std::ranges::find(localIds, id) != localIds.end(); };
    const auto removed = [&](const Element &e) { return listed(header(e).localId); };
    const auto first = std::ranges::find_if(elements, removed);
    const std::size_t firstIndex = std::size_t(first - elements.begin());
    for (quint64 id : localIds)
        m_index.remove(id);
    std::erase_if(elements, removed);
    // Wires from the removed elements go with them.
    for (Element &e : elements) {
        for (ConnectionPointIn *point : inputPoints(e))
            std::erase_if(point->connections, [&](const Connection &c) { return listed(c.refLocalId); });
    }
    reindexFrom(firstIndex);
}

void ElementPool::moveElement(int from, int to)
{
    if (from == to || from < 0 || to < 0 || from >= int(elements.size()) || to >= int(elements.size()))
        return;
    Element moved = std::move(elements[std::size_t(from)]);
    elements.erase(elements.begin() + from);
    elements.insert(elements.begin() + to, std::move(moved));
    reindexFrom(std::size_t(std::min(from, to)), std::size_t(std::max(from, to)) + 1);
}

void ElementPool::reindex()
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

void ElementPool::reindexFrom(std::size_t first, std::size_t last)
{
    last = std::min(last, elements.size());
    for (std::size_t i = first; i < last; ++i) {
        const quint64 id = header(elements[i]).localId;
        m_index.insert(id, i);
        idFloor = std::max(idFloor, id);
    }
}

int outputPinIndex(const Element &source, const std::optional<QString> &formalParameter)
{
    const auto *block = std::get_if<Block>(&source);
    if (!block)
        return 0;
    const std::vector<BlockVariable> &outputs = block->outputVariables;
    if (formalParameter && !formalParameter->isEmpty()) {
        for (std::size_t p = 0; p < outputs.size(); ++p)
            if (outputs[p].formalParameter.compare(*formalParameter, Qt::CaseInsensitive) == 0)
                return int(p);
        return -1;
    }
    return outputs.size() == 1 ? 0 : -1;
}

namespace {

void clearPlace(ConnectionPointIn &point)
{
    point.relPosition.reset();
    for (Connection &c : point.connections)
        c.waypoints.clear();
}

// The element without what the layout decides.
Element withoutPlace(Element e)
{
    ElementHeader &h = header(e);
    h.position = {};
    h.width.reset();
    h.height.reset();
    for (ConnectionPointIn *point : inputPoints(e))
        clearPlace(*point);
    std::visit(
        [](auto &x) {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, Block>) {
                for (auto *list : {&x.inputVariables, &x.inOutVariables, &x.outputVariables})
                    for (BlockVariable &v : *list) {
                        if (v.connectionPointIn)
                            clearPlace(*v.connectionPointIn);
                        if (v.connectionPointOut)
                            v.connectionPointOut->relPosition.reset();
                    }
            } else if constexpr (std::is_same_v<T, LeftPowerRail>) {
                x.connectionPointOuts.clear(); // one per wire, where the wires leave
            } else if constexpr (std::is_same_v<T, RightPowerRail>) {
                for (ConnectionPointIn &point : x.connectionPointIns)
                    clearPlace(point);
            } else if constexpr (requires { x.connectionPointOut; }) {
                if (x.connectionPointOut)
                    x.connectionPointOut->relPosition.reset();
            }
        },
        e);
    return e;
}

} // namespace

bool sameButPlace(const Element &a, const Element &b)
{
    return a.index() == b.index() && withoutPlace(a) == withoutPlace(b);
}

} // namespace iec::editors
