#include "editors/common/diagramview.h"

#include "editors/common/zoomsteps.h"

#include <QMouseEvent>
#include <QPainter>

#include <cmath>
#include <QScrollBar>
#include <QWheelEvent>

namespace iec::editors {

DiagramView::DiagramView(QWidget *parent)
    : QGraphicsView(parent)
{
    setDragMode(QGraphicsView::RubberBandDrag);
    setRenderHint(QPainter::Antialiasing);
    setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
    setResizeAnchor(QGraphicsView::AnchorViewCenter);
}

void DiagramView::setZoom(double factor)
{
    const double clamped = clampZoom(factor);
    if (qFuzzyCompare(clamped, m_zoom))
        return;
    m_zoom = clamped;
    setTransform(QTransform::fromScale(m_zoom, m_zoom));
    Q_EMIT zoomChanged(m_zoom);
}

void DiagramView::zoomIn() { setZoom(nextZoomIn(m_zoom)); }
void DiagramView::zoomOut() { setZoom(nextZoomOut(m_zoom)); }
void DiagramView::resetZoom() { setZoom(1.0); }

void DiagramView::fitToWindow()
{
    if (!scene())
        return;
    const QRectF drawing = scene()->itemsBoundingRect().adjusted(-10, -10, 10, 10);
    // A view not shown yet (a tab opened in the background, a picture taken offscreen) resizes
    // its viewport only when shown: until then the room is its inside as its parent sized it.
    const QSizeF room = isVisible() ? QSizeF(viewport()->size()) : QSizeF(contentsRect().size());
    if (drawing.isEmpty() || room.isEmpty())
        return;
    setZoom(std::min(room.width() / drawing.width(), room.height() / drawing.height()));
    centerOn(drawing.center());
}

void DiagramView::setGridSize(int size)
{
    m_gridSize = std::max(0, size);
    resetCachedContent();
    viewport()->update();
}

void DiagramView::drawBackground(QPainter *painter, const QRectF &rect)
{
    QGraphicsView::drawBackground(painter, rect);
    // Dots closer than 4 pixels on screen would only grey the background.
    if (m_gridSize <= 0 || m_gridSize * m_zoom < 4)
        return;
    painter->save();
    painter->setPen(QPen(QColor(0xc8, 0xc8, 0xc8), 0));
    const double left = std::floor(rect.left() / m_gridSize) * m_gridSize;
    const double top = std::floor(rect.top() / m_gridSize) * m_gridSize;
    QList<QPointF> dots;
    for (double x = left; x < rect.right(); x += m_gridSize)
        for (double y = top; y < rect.bottom(); y += m_gridSize)
            dots << QPointF(x, y);
    painter->drawPoints(dots.constData(), int(dots.size()));
    painter->restore();
}

void DiagramView::setBreakpointMarks(QList<QRectF> breakpoints, QRectF halted, QList<QRectF> disabled)
{
    if (breakpoints == m_breakpointMarks && halted == m_haltedMark && disabled == m_disabledMarks)
        return;
    const bool newHalt = !halted.isEmpty() && halted != m_haltedMark;
    m_breakpointMarks = std::move(breakpoints);
    m_disabledMarks = std::move(disabled);
    m_haltedMark = halted;
    if (newHalt)
        ensureVisible(halted, 40, 40);
    viewport()->update();
}

void DiagramView::drawForeground(QPainter *painter, const QRectF &rect)
{
    QGraphicsView::drawForeground(painter, rect);
    if (m_breakpointMarks.isEmpty() && m_disabledMarks.isEmpty() && m_haltedMark.isEmpty())
        return;
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    if (!m_haltedMark.isEmpty() && m_haltedMark.intersects(rect)) {
        // CODESYS shows where the program is halted in yellow.
        painter->setPen(QPen(QColor(0xe0, 0xa0, 0x00), 2));
        painter->setBrush(QColor(0xff, 0xeb, 0x3b, 90));
        painter->drawRect(m_haltedMark.adjusted(-3, -3, 3, 3));
    }
    painter->setPen(QPen(Qt::white, 1.5));
    painter->setBrush(QColor(0xd3, 0x2f, 0x2f));
    for (const QRectF &mark : std::as_const(m_breakpointMarks))
        painter->drawEllipse(QPointF(mark.left() + 3, mark.top() + 3), 6, 6);
    painter->setPen(QPen(QColor(0xd3, 0x2f, 0x2f), 2));
    painter->setBrush(Qt::NoBrush);
    for (const QRectF &mark : std::as_const(m_disabledMarks))
        painter->drawEllipse(QPointF(mark.left() + 3, mark.top() + 3), 5.5, 5.5);
    painter->restore();
}

void DiagramView::wheelEvent(QWheelEvent *event)
{
    if (!(event->modifiers() & Qt::ControlModifier)) {
        QGraphicsView::wheelEvent(event);
        return;
    }
    if (event->angleDelta().y() > 0)
        zoomIn();
    else if (event->angleDelta().y() < 0)
        zoomOut();
    event->accept();
}

void DiagramView::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::MiddleButton) {
        m_panning = true;
        m_lastPanPosition = event->position().toPoint();
        setCursor(Qt::ClosedHandCursor);
        event->accept();
        return;
    }
    QGraphicsView::mousePressEvent(event);
}

void DiagramView::mouseMoveEvent(QMouseEvent *event)
{
    if (m_panning) {
        const QPoint delta = event->position().toPoint() - m_lastPanPosition;
        m_lastPanPosition = event->position().toPoint();
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() - delta.x());
        verticalScrollBar()->setValue(verticalScrollBar()->value() - delta.y());
        event->accept();
        return;
    }
    QGraphicsView::mouseMoveEvent(event);
}

void DiagramView::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_panning && event->button() == Qt::MiddleButton) {
        m_panning = false;
        unsetCursor();
        event->accept();
        return;
    }
    QGraphicsView::mouseReleaseEvent(event);
}

} // namespace iec::editors
