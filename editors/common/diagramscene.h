#pragma once

#include "model/body.h"
#include "model/element.h"
#include "model/ids.h"

#include <QGraphicsScene>

#include <vector>

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {

class DiagramItem;

// What a language adds to the shared scene: which elements it shows and the items for them.
class DiagramPolicy
{
public:
    virtual ~DiagramPolicy() = default;
    // The elements shown (the body's, or a nested level's such as an SFC macro step's); nullptr
    // when there is nothing to show.
    virtual const std::vector<model::Element> *elements(const model::ProjectModel &model, const model::BodyRef &ref) const;
    // Adds the items for `elements` to the scene (DiagramItems for elements, plain items for wires).
    virtual void populate(QGraphicsScene &scene, const std::vector<model::Element> &elements) = 0;
};

// The scene of one graphical body, built from (model, body) and rebuilt when the model says
// the body changed. The selection is exported as localIds, which survive rebuilds.
class DiagramScene : public QGraphicsScene
{
    Q_OBJECT

public:
    DiagramScene(model::ProjectModel &model, model::BodyRef ref, DiagramPolicy &policy, QObject *parent = nullptr);

    [[nodiscard]] const model::BodyRef &bodyRef() const { return m_ref; }
    [[nodiscard]] model::ProjectModel &projectModel() const { return m_model; }

    [[nodiscard]] QList<quint64> selectedLocalIds() const;
    void selectLocalIds(const QList<quint64> &localIds);
    [[nodiscard]] DiagramItem *itemFor(quint64 localId) const;
    [[nodiscard]] QList<DiagramItem *> diagramItems() const;

    // Rebuilds now when the model changed since the last build (changes are collected and
    // rebuilt once, after the command that made them).
    void rebuildIfDirty();
    void rebuild();

Q_SIGNALS:
    void rebuilt();
    // A double-click on an element's item, with the point in scene coordinates (the language
    // decides: open a body, edit a property, zoom into a macro).
    void elementDoubleClicked(quint64 localId, QPointF scenePos);
    // A shift-click on an element: the language selects the connected range up to it.
    void elementShiftClicked(quint64 localId);

protected:
    void mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event) override;
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;

private:
    void scheduleRebuild(const model::BodyRef &ref);

    model::ProjectModel &m_model;
    model::BodyRef m_ref;
    DiagramPolicy &m_policy;
    bool m_dirty = false;
};

} // namespace iec::editors
