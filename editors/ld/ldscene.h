#pragma once

#include "editors/common/diagramscene.h"
#include "editors/common/networkitems.h"
#include "editors/ld/ldgeometry.h"
#include "editors/ld/ldnetwork.h"

#include <optional>

// The LD policy of the shared scene: the body read as networks, laid out automatically, one item
// per element, the rung's wires, and each network's band with its number, label and comment.
// Rung networks are always drawn in the editor's layout (the model gets it with the first edit);
// a freehand network is drawn where its elements are.
//
// A change is followed network by network: networks whose elements changed only in their
// positions (everything below an edit moves when a rung grows) keep their items and move them;
// only the edited networks get new items. So a command in a body of 1,000 networks touches one
// network's items, not the whole scene.
namespace iec::editors::ld {



class LdPolicy : public DiagramPolicy
{
public:
    const std::vector<model::Element> *elements(const model::ProjectModel &model, const model::BodyRef &ref) const override;
    void populate(DiagramScene &scene, const std::vector<model::Element> &elements) override;
    bool update(DiagramScene &scene, const std::vector<model::Element> &elements, const ElementChanges &changes) override;

    // What the scene shows now.
    [[nodiscard]] const LadderDocument &document() const { return m_document; }
    [[nodiscard]] const std::vector<NetworkGeometry> &layout() const { return m_layout; }
    [[nodiscard]] bool layoutGenerated() const { return m_layoutGenerated; }
    // Marks network `index` (0-based, -1 for none) as the cursor's; the others unmarked.
    void setCurrentNetwork(int index);
    // How many networks the last update built again (for tests and the bench).
    [[nodiscard]] int networksRebuiltLastTime() const { return m_rebuilt; }

    // The items of one network.
    struct NetworkItems {
        NetworkItem *band = nullptr;
        std::vector<quint64> elements;     // indexed in the scene
        std::vector<QGraphicsItem *> wires; // plain items
    };
    [[nodiscard]] const std::vector<NetworkItems> &networkItems() const { return m_items; }

private:

    LadderDocument read(const std::vector<model::Element> &elements);
    NetworkItems addNetwork(DiagramScene &scene, std::size_t index);
    void addFreehandWires(DiagramScene &scene, const LdNetwork &network, const NetworkGeometry &g, NetworkItems &items);
    static void removeItems(DiagramScene &scene, NetworkItems &items);
    static void moveItems(DiagramScene &scene, NetworkItems &items, double dy);

    mutable bool m_layoutGenerated = false;
    LadderDocument m_document;
    std::optional<LadderDocument> m_previous; // the document the last update replaced
    bool m_previousLayoutGenerated = false;
    std::vector<NetworkGeometry> m_layout;
    std::vector<NetworkItems> m_items;
    int m_rebuilt = 0;
};

// The item for one laid-out element (nullptr for elements drawn by the network band).
DiagramItem *createLadderItem(const LadderDocument &document, quint64 localId, const QRectF &rect, bool framedVariables);

// sameButPlace is shared (editors/common/elementpool.h).
using editors::sameButPlace;

} // namespace iec::editors::ld
