#pragma once

#include <QGraphicsItem>
#include <QList>
#include <QString>

namespace iec::editors {

// A place where a wire attaches to an element. Inputs are numbered as the model numbers them
// (model::inputPoints order), so a wire drawn to it becomes ProjectModel::connect(target,
// inputIndex, ...); an output is named by the formalParameter a connection from it carries
// (empty for an element's only output).
struct Pin {
    enum class Direction { In, Out };

    Direction direction = Direction::In;
    QPointF scenePos;
    int inputIndex = -1;     // In: index in model::inputPoints(element)
    QString formalParameter; // Out: the connection's formalParameter; empty for the only output
    QString name;            // what the pin is called on the element (tooltips, assistants)

    bool operator==(const Pin &) const = default;
};

// A compiler message shown on an element: a frame around it and the message as its tooltip.
struct ElementDiagnostic {
    enum class Severity { Warning, Error };

    quint64 localId = 0;
    Severity severity = Severity::Error;
    QString message;

    bool operator==(const ElementDiagnostic &) const = default;
};

// The base of every item that stands for one element of a graphical body. It is thin: it knows
// its element's localId and draws; the language's policy decides what it looks like and the
// model stays the only place that holds the element (items are made again from it).
class DiagramItem : public QGraphicsItem
{
public:
    enum { Type = UserType + 0x100 };

    explicit DiagramItem(quint64 localId, QGraphicsItem *parent = nullptr);
    ~DiagramItem() override;

    [[nodiscard]] quint64 localId() const { return m_localId; }
    int type() const override { return Type; }

    // The element's own rectangle in scene coordinates, without texts that stick out (what
    // navigation measures from and diagnostics frame). Default: the bounding rectangle.
    [[nodiscard]] virtual QRectF frame() const;
    // Where wires attach, in scene coordinates. Default: none.
    [[nodiscard]] virtual QList<Pin> pins() const;

    // Online mode: the overlay restyles the item without touching the model.
    [[nodiscard]] bool isActive() const { return m_active; }
    void setActive(bool active);
    [[nodiscard]] QString onlineText() const { return m_onlineText; }
    void setOnlineText(const QString &text);

    // A compiler message on the element: a frame around frame() (red for errors, orange for
    // warnings) and the message as the tooltip.
    void setDiagnostic(ElementDiagnostic::Severity severity, const QString &message);
    void clearDiagnostic();
    [[nodiscard]] QString diagnosticMessage() const { return m_diagnostic; }

private:
    quint64 m_localId;
    bool m_active = false;
    QString m_onlineText;
    QString m_diagnostic;
    QString m_toolTipBefore; // the item's own tooltip while the message covers it
    QGraphicsItem *m_diagnosticMark = nullptr;
};

// The DiagramItem an item belongs to (itself, or an ancestor), nullptr for decorations.
DiagramItem *diagramItemOf(QGraphicsItem *item);

} // namespace iec::editors
