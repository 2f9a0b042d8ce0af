#pragma once

#include "model/body.h"
#include "model/element.h"

#include <QHash>

#include <vector>

namespace iec::editors {

// The elements of a graphical body (in file order) with an index by localId, as the structured
// editors (LD networks, FBD networks) hold them while a command rewrites them. Ids handed out are
// never below the largest the pool has held, so an edit that removes an element and adds another
// does not reuse the removed one's id (undo relies on ids being distinct).
struct ElementPool {
    std::vector<model::Element> elements;
    quint64 idFloor = 0;

    [[nodiscard]] const model::Element *element(quint64 localId) const;
    model::Element *element(quint64 localId);
    [[nodiscard]] int indexOf(quint64 localId) const; // in `elements`, -1 when absent
    [[nodiscard]] quint64 allocateId();
    // Gives the element a fresh localId and inserts it at `index` (-1: the end).
    quint64 add(model::Element element, int index = -1);
    // Removes the elements and every wire from them.
    void removeElements(const std::vector<quint64> &localIds);
    // Moves the element at `from` so that it ends up at index `to` of `elements`.
    void moveElement(int from, int to);
    void reindex(); // after `elements` changed by hand
    // After the elements from `first` on changed places or were inserted (cheaper than reindex on
    // a large body: the ids before `first` keep their entries).
    void reindexFrom(std::size_t first, std::size_t last = std::size_t(-1));

private:
    // A QHash, not a std::unordered_map: the editors copy the pool on every command, and a QHash
    // copies its buckets in a few blocks instead of one allocation per element.
    QHash<quint64, std::size_t> m_index;
};

// The output pin of `source` a connection names (by its formalParameter; a box's only output when
// it names none), -1 when the source has no such pin. Elements other than boxes have pin 0.
int outputPinIndex(const model::Element &source, const std::optional<QString> &formalParameter);

// Whether two elements differ only where a layout puts them (positions, sizes, pin positions,
// wire corners): then an editor that lays its networks out draws them the same, only elsewhere.
bool sameButPlace(const model::Element &a, const model::Element &b);

} // namespace iec::editors
