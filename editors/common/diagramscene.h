#pragma once

#include "editors/common/diagramitem.h"
#include "model/body.h"
#include "model/element.h"
#include "model/ids.h"

#include <QGraphicsScene>
#include <QHash>
#include <QSet>

#include <optional>
#include <vector>

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {

class DiagramScene;

// What changed in the shown body since the scene was last brought up to date, by localId, as
// the model's signals said it (an element inserted and removed again within one command is in
// neither set; one removed and inserted again is changed).
struct ElementChanges {
    QSet<quint64> inserted;
    QSet<quint64> removed;
    QSet<quint64> changed; // its value (properties, position, connections) or its place in the list

    [[nodiscard]] bool isEmpty() const { return inserted.isEmpty() && removed.isEmpty() && changed.isEmpty(); }
    bool operator==(const ElementChanges &) const = default;
};

// What a language adds to the shared scene: which elements it shows, the items for them, and
// how it follows a change. The scene owns no language knowledge.
class DiagramPolicy
{
public:
    virtual ~DiagramPolicy() = default;
    // The elements shown (the body's, or a nested level's such as an SFC macro step's); nullptr
    // when there is nothing to show.
    virtual const std::vector<model::Element> *elements(const model::ProjectModel &model, const model::BodyRef &ref) const;
    // Adds the items for `elements` to an empty scene: DiagramItems through
    // scene.addElementItem (which indexes them by localId), plain items (wires, rails) through
    // scene.addItem.
    virtual void populate(DiagramScene &scene, const std::vector<model::Element> &elements) = 0;
    // Follows `changes` without rebuilding everything (remove, replace and add the items
    // concerned, at whatever granularity the language needs: an LD network, a CFC element and its
    // wires). `elements` is the new content. Returns false to ask for a full rebuild instead
    // (the default: right for small bodies and for layouts that depend on everything).
    virtual bool update(DiagramScene &scene, const std::vector<model::Element> &elements, const ElementChanges &changes);

    // Editing by mouse (CFC, freehand LD): whether an element may be dragged to another place,
    // and whether an output pin may be wired to an input pin. SFC charts and LD rungs place
    // everything themselves: no.
    [[nodiscard]] virtual bool isMovable(const model::Element &element) const;
    // Whether a rubber wire may start at this pin, and whether it may end as a connection from
    // `output` to `input`.
    [[nodiscard]] virtual bool canStartWire(const DiagramItem &item, const Pin &pin) const;
    [[nodiscard]] virtual bool canConnect(const DiagramItem &source, const Pin &output, const DiagramItem &target,
        const Pin &input) const;
    // While a drag moves the items of `localIds` by `delta` from where the model has them (before
    // the move becomes a command): CFC re-routes their wires. Default: nothing.
    virtual void itemsDragged(DiagramScene &scene, const QList<quint64> &localIds, QPointF delta);
};

// A pin of an item together with the item (what the mouse found).
struct PinHit {
    DiagramItem *item = nullptr;
    Pin pin;
};

// The scene of one graphical body, built from (model, body) through a policy. It collects the
// localIds the model's signals carry until the command that sent them is done, then asks the
// policy to update just those (or rebuilds when the policy declines); an index finds the item
// of a localId in constant time. The selection is kept as localIds across both.
//
// Mouse editing (when the policy allows it and the scene is editable): dragging selected movable
// items ends in one elementsMoved (the editor turns it into one MoveElementsCommand), dragging
// from a pin to a pin of the other direction draws a rubber wire and ends in one wireDrawn.
class DiagramScene : public QGraphicsScene
{
    Q_OBJECT

public:
    DiagramScene(model::ProjectModel &model, model::BodyRef ref, DiagramPolicy &policy, QObject *parent = nullptr);
    ~DiagramScene() override;

    [[nodiscard]] const model::BodyRef &bodyRef() const { return m_ref; }
    [[nodiscard]] model::ProjectModel &projectModel() const { return m_model; }
    [[nodiscard]] DiagramPolicy &policy() const { return m_policy; }
    // The elements shown now (the policy's view of the body), nullptr when there are none.
    [[nodiscard]] const std::vector<model::Element> *shownElements() const;

    // ---- items by localId (for the policy)
    // Adds an element's item to the scene (unless it is the child of an item there already)
    // and indexes it. An item deleted later leaves the index by itself.
    void addElementItem(DiagramItem *item);
    // Deletes the item of `localId` (and its children), if there is one.
    void removeElementItem(quint64 localId);
    [[nodiscard]] DiagramItem *itemFor(quint64 localId) const { return m_index.value(localId); }
    // The element under a point: the topmost item there that takes mouse clicks, as its element
    // (decorations that take none, such as a cursor frame drawn over an element, are looked
    // through); nullptr over a wire or the background.
    [[nodiscard]] DiagramItem *diagramItemAt(QPointF scenePos) const;
    // Every indexed item in stacking order (for navigation and tests; linear time).
    [[nodiscard]] QList<DiagramItem *> diagramItems() const;

    // ---- selection, as localIds (sorted)
    [[nodiscard]] QList<quint64> selectedLocalIds() const;
    void selectLocalIds(const QList<quint64> &localIds);

    // ---- pins
    // The pin nearest to `scenePoint` within `radius`, of any item there.
    [[nodiscard]] std::optional<PinHit> pinAt(QPointF scenePoint, double radius = 6) const;

    // ---- keeping up with the model
    // Brings the scene up to date now when the model changed since (incrementally when the
    // policy can). Editors call it right after pushing a command, to select what it made.
    void rebuildIfDirty();
    // Builds every item again from the model.
    void rebuild();
    // Online the scene is only looked at: no dragging, no wiring (selection stays).
    void setEditable(bool editable) { m_editable = editable; }
    [[nodiscard]] bool isEditable() const { return m_editable; }
    // The grid that moved items snap to (the settings' grid size; 0: no snapping).
    void setGridSize(int size) { m_gridSize = size; }
    [[nodiscard]] int gridSize() const { return m_gridSize; }

Q_SIGNALS:
    // After a full rebuild (every item is new).
    void rebuilt();
    // After the policy followed `changes` (the other items are the same objects as before).
    void updated(const iec::editors::ElementChanges &changes);
    // A double-click on an element's item, with the point in scene coordinates (the language
    // decides: open a body, edit a property, zoom into a macro).
    void elementDoubleClicked(quint64 localId, QPointF scenePos);
    // A shift-click on an element: the language selects the connected range up to it.
    void elementShiftClicked(quint64 localId);
    // A drag of the selected movable items ended: each to its new position (snapped to the grid;
    // the model's positions, not moved yet: the editor pushes one command).
    void elementsMoved(const QList<quint64> &localIds, const QList<QPointF> &positions);
    // A wire was drawn from an output pin to an input pin (either way round).
    void wireDrawn(quint64 source, const QString &sourceFormalParameter, quint64 target, int targetInputIndex);

protected:
    void mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event) override;
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override;

private:
    friend class DiagramItem;
    void forget(DiagramItem *item);
    void noteInserted(const model::BodyRef &ref, const QList<quint64> &localIds);
    void noteRemoved(const model::BodyRef &ref, const QList<quint64> &localIds);
    void noteChanged(const model::BodyRef &ref, const QList<quint64> &localIds);
    void noteEverything();
    void schedule();
    void growSceneRect(const ElementChanges &changes);
    bool beginWire(QGraphicsSceneMouseEvent *event);
    void finishWire(QPointF scenePos);
    void beginMove(QGraphicsSceneMouseEvent *event);
    void finishMove();

    model::ProjectModel &m_model;
    model::BodyRef m_ref;
    DiagramPolicy &m_policy;
    QHash<quint64, DiagramItem *> m_index;
    ElementChanges m_pending;
    bool m_needsRebuild = false;
    bool m_scheduled = false;
    bool m_editable = true;
    int m_gridSize = 0;

    // A drag in progress: the items' positions when it began.
    struct Drag {
        QPointF pressedAt;
        quint64 anchor = 0; // the item pressed: its position decides the snapping
        QHash<quint64, QPointF> modelPositions; // the elements' positions in the model
        QHash<quint64, QPointF> itemPositions;  // the items' pos()
        QPointF delta;                          // snapped, so far
    };
    std::optional<Drag> m_drag;
    // A wire being drawn: where it started and the rubber line.
    struct Draft {
        PinHit from;
        QGraphicsLineItem *line = nullptr;
    };
    std::optional<Draft> m_draft;
};

} // namespace iec::editors
