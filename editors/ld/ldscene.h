#pragma once

#include "editors/common/diagramscene.h"
#include "editors/ld/ldgeometry.h"
#include "editors/ld/ldnetwork.h"

#include <QHash>

// The LD policy of the shared scene: the body read as networks, laid out automatically, one item
// per element, the rung's wires, and each network's band with its number, label and comment.
// Rung networks are always drawn in the editor's layout (the model gets it with the first edit);
// a freehand network is drawn where its elements are.
namespace iec::editors::ld {

class LdPolicy : public DiagramPolicy
{
public:
    const std::vector<model::Element> *elements(const model::ProjectModel &model, const model::BodyRef &ref) const override;
    void populate(QGraphicsScene &scene, const std::vector<model::Element> &elements) override;

    // What the scene shows now (after the last populate).
    [[nodiscard]] const LadderDocument &document() const { return m_document; }
    [[nodiscard]] const std::vector<NetworkGeometry> &layout() const { return m_layout; }
    [[nodiscard]] bool layoutGenerated() const { return m_layoutGenerated; }

private:
    void addNetwork(QGraphicsScene &scene, std::size_t index);
    void addFreehandWires(QGraphicsScene &scene, const LdNetwork &network, const NetworkGeometry &g);

    mutable bool m_layoutGenerated = false;
    LadderDocument m_document;
    std::vector<NetworkGeometry> m_layout;
};

// The item for one laid-out element (nullptr for elements drawn by the network band).
DiagramItem *createLadderItem(const LadderDocument &document, quint64 localId, const QRectF &rect, bool framedVariables);

} // namespace iec::editors::ld
