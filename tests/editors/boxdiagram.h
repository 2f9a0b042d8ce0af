#pragma once
// A tiny graphical language for the framework's tests: every element is a 40 x 20 box at its
// position; an in-variable has an output pin on its right side, an out-variable an input pin on
// its left side. The policy counts full builds and updates, and can follow changes itself.
#include "editors/common/diagramitem.h"
#include "editors/common/diagramscene.h"
#include "model/element.h"

#include <QPainter>

namespace iec::tests {

class BoxItem : public editors::DiagramItem
{
public:
    explicit BoxItem(const model::Element &element)
        : DiagramItem(model::header(element).localId)
        , m_rect(model::header(element).position.x, model::header(element).position.y, 40, 20)
        , m_hasInput(std::holds_alternative<model::OutVariable>(element))
        , m_hasOutput(std::holds_alternative<model::InVariable>(element))
    {
    }
    QRectF boundingRect() const override { return m_rect; }
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *) override { painter->drawRect(m_rect); }
    QList<editors::Pin> pins() const override
    {
        QList<editors::Pin> list;
        const QPointF offset = pos();
        if (m_hasInput)
            list << editors::Pin {editors::Pin::Direction::In, QPointF(m_rect.left(), m_rect.center().y()) + offset, 0, {},
                QStringLiteral("IN")};
        if (m_hasOutput)
            list << editors::Pin {editors::Pin::Direction::Out, QPointF(m_rect.right(), m_rect.center().y()) + offset, -1,
                {}, QStringLiteral("OUT")};
        return list;
    }

private:
    QRectF m_rect;
    bool m_hasInput;
    bool m_hasOutput;
};

class BoxPolicy : public editors::DiagramPolicy
{
public:
    int populated = 0;
    int updates = 0;
    bool followsChanges = false; // update() instead of a rebuild
    bool mouseEditing = false;   // movable boxes, wirable pins
    std::vector<editors::ElementChanges> changes;

    void populate(editors::DiagramScene &scene, const std::vector<model::Element> &elements) override
    {
        ++populated;
        for (const model::Element &element : elements)
            scene.addElementItem(new BoxItem(element));
    }
    bool update(editors::DiagramScene &scene, const std::vector<model::Element> &elements,
        const editors::ElementChanges &change) override
    {
        if (!followsChanges)
            return false;
        ++updates;
        changes.push_back(change);
        for (quint64 id : change.removed)
            scene.removeElementItem(id);
        for (const model::Element &element : elements) {
            const quint64 id = model::header(element).localId;
            if (change.changed.contains(id))
                scene.removeElementItem(id);
            if (change.changed.contains(id) || change.inserted.contains(id))
                scene.addElementItem(new BoxItem(element));
        }
        return true;
    }
    bool isMovable(const model::Element &) const override { return mouseEditing; }
    bool canStartWire(const editors::DiagramItem &, const editors::Pin &) const override { return mouseEditing; }
    bool canConnect(const editors::DiagramItem &, const editors::Pin &, const editors::DiagramItem &,
        const editors::Pin &) const override
    {
        return mouseEditing;
    }
};

inline model::Element commentAt(double x, double y)
{
    model::Comment comment;
    comment.position = {x, y};
    return comment;
}

inline model::Element inVariableAt(double x, double y, const QString &expression)
{
    model::InVariable variable;
    variable.position = {x, y};
    variable.expression = expression;
    variable.connectionPointOut = model::ConnectionPointOut {};
    return variable;
}

inline model::Element outVariableAt(double x, double y, const QString &expression)
{
    model::OutVariable variable;
    variable.position = {x, y};
    variable.expression = expression;
    variable.connectionPointIn = model::ConnectionPointIn {};
    return variable;
}

} // namespace iec::tests
