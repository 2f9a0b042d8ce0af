#pragma once

#include <QGraphicsView>

namespace iec::editors {

// The view every graphical editor (LD, FBD, CFC, SFC) uses: zoom steps, Ctrl+wheel zoom,
// middle-button pan, rubber-band selection.
class DiagramView : public QGraphicsView
{
    Q_OBJECT

public:
    explicit DiagramView(QWidget *parent = nullptr);

    [[nodiscard]] double zoom() const { return m_zoom; }
    void setZoom(double factor);
    void zoomIn();
    void zoomOut();
    void resetZoom();
    // Zooms so that the whole drawing fits the window (between the smallest and largest step).
    void fitToWindow();

    // A dotted grid behind the drawing (the grid size of the settings; 0 hides it).
    void setGridSize(int size);
    [[nodiscard]] int gridSize() const { return m_gridSize; }

    // Debugging marks over the drawing (scene rectangles): a red dot at the top left of each
    // breakpoint's place, the place the program is halted at tinted yellow (an empty rectangle:
    // none). Not part of the scene, so exports and prints leave them out.
    void setBreakpointMarks(QList<QRectF> breakpoints, QRectF halted, QList<QRectF> disabled = {});
    [[nodiscard]] const QList<QRectF> &breakpointMarks() const { return m_breakpointMarks; }
    [[nodiscard]] const QList<QRectF> &disabledBreakpointMarks() const { return m_disabledMarks; } // drawn hollow
    [[nodiscard]] QRectF haltedMark() const { return m_haltedMark; }

Q_SIGNALS:
    void zoomChanged(double factor);

protected:
    void drawBackground(QPainter *painter, const QRectF &rect) override;
    void drawForeground(QPainter *painter, const QRectF &rect) override;
    void wheelEvent(QWheelEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    double m_zoom = 1.0;
    bool m_panning = false;
    QPoint m_lastPanPosition;
    int m_gridSize = 0;
    QList<QRectF> m_breakpointMarks;
    QList<QRectF> m_disabledMarks;
    QRectF m_haltedMark;
};

} // namespace iec::editors
