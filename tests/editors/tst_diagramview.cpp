#include "editors/common/diagramview.h"
#include "editors/common/zoomsteps.h"

#include <QGraphicsScene>
#include <QSignalSpy>
#include <QTest>

using namespace iec::editors;

class TestDiagramView : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void zoomSteps_data();
    void zoomSteps();
    void viewAppliesZoomToItsTransform();
    void ctrlWheelZooms();
};

void TestDiagramView::zoomSteps_data()
{
    QTest::addColumn<double>("current");
    QTest::addColumn<double>("in");
    QTest::addColumn<double>("out");
    QTest::newRow("100%") << 1.0 << 1.25 << 0.75;
    QTest::newRow("between steps") << 1.1 << 1.25 << 1.0;
    QTest::newRow("a hair above a step") << 1.0004 << 1.25 << 0.75;
    QTest::newRow("minimum") << 0.25 << 0.33 << 0.25;
    QTest::newRow("maximum") << 4.0 << 4.0 << 3.0;
    QTest::newRow("below range") << 0.1 << 0.25 << 0.25;
}

void TestDiagramView::zoomSteps()
{
    QFETCH(double, current);
    QFETCH(double, in);
    QFETCH(double, out);
    QCOMPARE(nextZoomIn(current), in);
    QCOMPARE(nextZoomOut(current), out);
}

void TestDiagramView::viewAppliesZoomToItsTransform()
{
    QGraphicsScene scene;
    scene.addRect(0, 0, 100, 50);
    DiagramView view;
    view.setScene(&scene);
    QSignalSpy changed(&view, &DiagramView::zoomChanged);

    view.zoomIn();
    view.zoomIn();
    QCOMPARE(view.zoom(), 1.5);
    QCOMPARE(view.transform().m11(), 1.5);
    QCOMPARE(view.transform().m22(), 1.5);

    view.setZoom(10.0);
    QCOMPARE(view.zoom(), maximumZoom());
    view.resetZoom();
    QCOMPARE(view.transform().m11(), 1.0);
    QCOMPARE(changed.count(), 4);
}

void TestDiagramView::ctrlWheelZooms()
{
    DiagramView view;
    view.resize(200, 200);
    view.show();
    const QPointF center(100, 100);
    QWheelEvent up(center, view.mapToGlobal(center), {}, {0, 120}, Qt::NoButton, Qt::ControlModifier,
                   Qt::NoScrollPhase, false);
    QApplication::sendEvent(view.viewport(), &up);
    QCOMPARE(view.zoom(), 1.25);

    QWheelEvent plain(center, view.mapToGlobal(center), {}, {0, -120}, Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(view.viewport(), &plain);
    QCOMPARE(view.zoom(), 1.25); // without Ctrl the wheel scrolls
}

QTEST_MAIN(TestDiagramView)
#include "tst_diagramview.moc"
