#pragma once

#include "editors/cfc/cfcgeometry.h"
#include "editors/cfc/cfcstorage.h"
#include "editors/common/diagramscene.h"

#include <functional>
#include <map>
#include <optional>
#include <tuple>

namespace iec::editors {
class WireItem;
}

namespace iec::editors::cfc {

// How a CFC body is drawn: every element where it stands, its execution-order number in the
// corner, and every wire routed around the elements near it (red and straight where there is no
// room). A change redraws the elements concerned and re-routes only the wires that touch them or
// ran where they stand; a drag re-routes the dragged elements' wires as the mouse moves.
class CfcPolicy : public DiagramPolicy
{
public:
    const std::vector<model::Element> *elements(const model::ProjectModel &model, const model::BodyRef &ref) const override;
    void populate(DiagramScene &scene, const std::vector<model::Element> &elements) override;
    bool update(DiagramScene &scene, const std::vector<model::Element> &elements, const ElementChanges &changes) override;

    [[nodiscard]] bool isMovable(const model::Element &element) const override;
    [[nodiscard]] bool canStartWire(const DiagramItem &item, const Pin &pin) const override;
    [[nodiscard]] bool canConnect(const DiagramItem &source, const Pin &output, const DiagramItem &target,
        const Pin &input) const override;
    void itemsDragged(DiagramScene &scene, const QList<quint64> &localIds, QPointF delta) override;

    // Where the body keeps the diagram (nullopt: not a CFC body, or CODESYS content that cannot be
    // read: readError() says why).
    [[nodiscard]] std::optional<CfcStorage> storage() const { return m_storage; }
    [[nodiscard]] QString readError() const { return m_readError; }
    // The wires as drawn now (tests, the overlay).
    [[nodiscard]] std::vector<CfcWire> wires() const;
    // Each wire with its item (the overlay colours them).
    void forEachWire(const std::function<void(const CfcWire &, WireItem &)> &visit) const;
    [[nodiscard]] const CfcFrames &frames() const { return m_frames; }

private:
    using WireKey = std::tuple<quint64, QString, quint64, int>; // source, its output, target, pin
    struct DrawnWire {
        CfcWire wire;
        WireItem *item = nullptr;
    };

    void addElementItem(DiagramScene &scene, const model::Element &element);
    // Re-routes the wires that touch `touched` or pass through `dirty` (and the broken ones, which
    // may have room now), keeps the others, and drops the wires that are gone.
    void refreshWires(DiagramScene &scene, const std::vector<model::Element> &elements, const QSet<quint64> &touched,
        const QList<QRectF> &dirty, bool everything);

    mutable std::optional<CfcStorage> m_storage;
    mutable QString m_readError;
    mutable QString m_codesysContent; // what m_codesysElements were read from
    mutable std::vector<model::Element> m_codesysElements;
    CfcFrames m_frames;
    std::map<WireKey, DrawnWire> m_wires;
};

} // namespace iec::editors::cfc
