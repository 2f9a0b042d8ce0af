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

Q_SIGNALS:
    void zoomChanged(double factor);

protected:
    void wheelEvent(QWheelEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    double m_zoom = 1.0;
    bool m_panning = false;
    QPoint m_lastPanPosition;
};

} // namespace iec::editors
