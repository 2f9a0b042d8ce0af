// Breakpoint marks of the graphical editors (docs/debugging.md): the place at the cursor for F9,
// and the marks drawn over the drawing by the view.
#include "editors/common/diagrameditor.h"
#include "editors/common/diagramitem.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"

namespace iec::editors {

std::vector<quint64> DiagramEditor::breakpointElementsAtCursor() const
{
    const std::vector<quint64> selected = selectedIds();
    if (selected.empty())
        return {};
    return {selected.front()};
}

QRectF DiagramEditor::breakpointAnchor(qint64 localId) const
{
    if (localId < 0)
        return {};
    if (const int network = networkOfElement(localId); network >= 0)
        return networkBand(network);
    const DiagramItem *item = m_scene->itemFor(quint64(localId));
    return item ? item->sceneBoundingRect() : QRectF();
}

QString DiagramEditor::placeName(qint64 localId) const
{
    const int network = localId < 0 ? -1 : networkOfElement(localId);
    return network < 0 ? QString() : tr("network %1").arg(network + 1);
}

std::optional<OnlineView::Place> DiagramEditor::breakpointPlace() const
{
    const std::vector<quint64> elements = breakpointElementsAtCursor();
    if (elements.empty())
        return std::nullopt;
    Place place;
    place.localId = qint64(elements.front());
    for (const quint64 id : elements)
        place.elements.push_back(qint64(id));
    return place;
}

void DiagramEditor::setBreakpointMarks(const std::vector<Place> &breakpoints, std::optional<Place> halted)
{
    m_breakpointPlaces = breakpoints;
    m_haltedPlace = std::move(halted);
    refreshBreakpointMarks();
}

void DiagramEditor::refreshBreakpointMarks()
{
    if (!m_view)
        return;
    QList<QRectF> marks;
    QList<QRectF> disabled;
    for (const Place &place : m_breakpointPlaces)
        if (const QRectF anchor = breakpointAnchor(place.localId); !anchor.isEmpty())
            (place.enabled ? marks : disabled).append(anchor);
    const QRectF halted = m_haltedPlace ? breakpointAnchor(m_haltedPlace->localId) : QRectF();
    m_view->setBreakpointMarks(marks, halted, disabled);
}

} // namespace iec::editors
