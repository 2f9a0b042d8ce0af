#pragma once

#include <QGraphicsItem>

namespace iec::editors {

// The base of every item that stands for one element of a graphical body. It is thin: it knows
// its element's localId and draws; the language's policy decides what it looks like and the
// model stays the only place that holds the element (items are rebuilt from it).
class DiagramItem : public QGraphicsItem
{
public:
    enum { Type = UserType + 0x100 };

    explicit DiagramItem(quint64 localId, QGraphicsItem *parent = nullptr);

    [[nodiscard]] quint64 localId() const { return m_localId; }
    int type() const override { return Type; }

    // Online mode: the overlay restyles the item without touching the model.
    [[nodiscard]] bool isActive() const { return m_active; }
    void setActive(bool active);
    [[nodiscard]] QString onlineText() const { return m_onlineText; }
    void setOnlineText(const QString &text);

private:
    quint64 m_localId;
    bool m_active = false;
    QString m_onlineText;
};

// The DiagramItem an item belongs to (itself, or an ancestor), nullptr for decorations.
DiagramItem *diagramItemOf(QGraphicsItem *item);

} // namespace iec::editors
