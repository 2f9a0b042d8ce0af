#pragma once

#include "editors/common/diagramscene.h"
#include "editors/common/networkitems.h"
#include "editors/fbd/fbdlayout.h"

#include <optional>

// The FBD policy of the shared scene: the body read as networks, each laid out automatically
// (fbdlayout.h), one item per element (the box, variable and wire items LD draws too), and each
// network's band with its number, label and comment. A tree network is always drawn in the
// editor's layout (the model gets it with the first edit); a freehand one where its elements are.
//
// A change is followed network by network: networks whose elements changed only in their places
// keep their items and move; only the edited networks get new items.
namespace iec::editors::fbd {

class FbdPolicy : public DiagramPolicy
{
public:
    const std::vector<model::Element> *elements(const model::ProjectModel &model, const model::BodyRef &ref) const override;
    void populate(DiagramScene &scene, const std::vector<model::Element> &elements) override;
    bool update(DiagramScene &scene, const std::vector<model::Element> &elements, const ElementChanges &changes) override;

    // What the scene shows now.
    [[nodiscard]] const FbdDocument &document() const { return m_document; }
    [[nodiscard]] const std::vector<FbdGeometry> &layout() const { return m_layout; }
    [[nodiscard]] bool layoutGenerated() const { return m_layoutGenerated; }
    // Marks network `index` (-1: none) as the cursor's.
    void setCurrentNetwork(int index);
    // How many networks the last update built again (tests, bench).
    [[nodiscard]] int networksRebuiltLastTime() const { return m_rebuilt; }

    struct NetworkItems {
        NetworkItem *band = nullptr;
        std::vector<quint64> elements;      // indexed in the scene
        std::vector<QGraphicsItem *> wires; // plain items
    };
    [[nodiscard]] const std::vector<NetworkItems> &networkItems() const { return m_items; }

private:
    FbdDocument read(const std::vector<model::Element> &elements);
    NetworkItems addNetwork(DiagramScene &scene, std::size_t index);
    static void removeItems(DiagramScene &scene, NetworkItems &items);
    static void moveItems(DiagramScene &scene, NetworkItems &items, double dy);

    mutable bool m_layoutGenerated = false;
    FbdDocument m_document;
    std::optional<FbdDocument> m_previous; // the document the last update replaced (undo reuses it)
    bool m_previousLayoutGenerated = false;
    std::vector<FbdGeometry> m_layout;
    std::vector<NetworkItems> m_items;
    int m_rebuilt = 0;
};

// The item for one laid-out element (nullptr for elements the band draws: labels, comments).
DiagramItem *createFbdItem(const FbdDocument &document, const FbdGeometry &g, quint64 localId, bool freehand);

} // namespace iec::editors::fbd
