#pragma once

#include "editors/common/blockitems.h"

#include <algorithm>
#include <initializer_list>
#include <vector>

// Items the network languages share (LD, FBD): outputs that end a network (jumps, returns) and the
// band of a network (its number, label and comment).
namespace iec::editors {

// Jump (an arrow and the label), return (<RETURN>), and anything else drawn as a labelled frame.
class OutputMarkItem : public ElementItem
{
public:
    OutputMarkItem(const model::Element &element, const QRectF &rect);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
};

// A network's band: its number (0001, as CODESYS counts), a separator line, its label and
// comment. Clicking the number puts the cursor on the network.
class NetworkItem : public QGraphicsItem
{
public:
    enum { Type = UserType + 0x150 };

    NetworkItem(int number, const QRectF &band, const QString &label, const QRectF &labelRect, const QString &comment,
        const QRectF &commentRect, bool freehand);
    int type() const override { return Type; }
    QRectF boundingRect() const override { return m_band; }
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

    [[nodiscard]] int number() const { return m_number; }
    void setNumber(int number);
    void setCurrent(bool current);
    // Online: a breakpoint or the halt position may colour the number later; kept simple here.
    [[nodiscard]] QRectF numberRect() const;

private:
    int m_number;
    QRectF m_band;
    QString m_label;
    QRectF m_labelRect;
    QString m_comment;
    QRectF m_commentRect;
    bool m_freehand;
    bool m_current = false;
};

// Breakpoints in LD and FBD are on whole networks (docs/debugging.md). The elements one stands
// for: the network's members but `aside` (its rails, label, comment).
template<typename Network>
std::vector<quint64> networkMembersExcept(const Network &network, std::initializer_list<quint64> aside)
{
    std::vector<quint64> members;
    for (const quint64 id : network.members)
        if (std::ranges::find(aside, id) == aside.end())
            members.push_back(id);
    return members;
}

// The band of network `index` among a policy's network items, in scene coordinates; empty when
// there is none.
template<typename NetworkItems>
QRectF networkBandRect(const std::vector<NetworkItems> &items, int index)
{
    if (index < 0 || index >= int(items.size()) || !items[std::size_t(index)].band)
        return {};
    return items[std::size_t(index)].band->sceneBoundingRect();
}

} // namespace iec::editors
