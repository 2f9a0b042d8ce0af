#include "editors/common/grid.h"
#include "editors/common/wirerouting.h"

#include <QTest>

using namespace iec::editors;

using Polyline = QList<QPointF>;

class TestGeometry : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void snapping_data();
    void snapping();
    void snappedRectKeepsAtLeastOneCell();
    void simplify_data();
    void simplify();
    void routes_data();
    void routes();
    void routesAreOrthogonalAndAvoidObstacles_data();
    void routesAreOrthogonalAndAvoidObstacles();
};

void TestGeometry::snapping_data()
{
    QTest::addColumn<QPointF>("point");
    QTest::addColumn<int>("grid");
    QTest::addColumn<QPointF>("snapped");
    QTest::newRow("on grid") << QPointF(20, 40) << 10 << QPointF(20, 40);
    QTest::newRow("rounds down") << QPointF(24, 41) << 10 << QPointF(20, 40);
    QTest::newRow("rounds up") << QPointF(25, 46) << 10 << QPointF(30, 50);
    QTest::newRow("negative") << QPointF(-14, -16) << 10 << QPointF(-10, -20);
    QTest::newRow("grid off") << QPointF(13.5, 7.25) << 1 << QPointF(13.5, 7.25);
}

void TestGeometry::snapping()
{
    QFETCH(QPointF, point);
    QFETCH(int, grid);
    QFETCH(QPointF, snapped);
    QCOMPARE(snapToGrid(point, grid), snapped);
}

void TestGeometry::snappedRectKeepsAtLeastOneCell()
{
    QCOMPARE(snapToGrid(QRectF(12, 18, 3, 44), 10), QRectF(10, 20, 10, 40));
}

void TestGeometry::simplify_data()
{
    QTest::addColumn<Polyline>("input");
    QTest::addColumn<Polyline>("expected");
    QTest::newRow("straight run") << Polyline{{0, 0}, {10, 0}, {20, 0}} << Polyline{{0, 0}, {20, 0}};
    QTest::newRow("duplicates") << Polyline{{0, 0}, {0, 0}, {0, 10}, {0, 10}} << Polyline{{0, 0}, {0, 10}};
    QTest::newRow("bend kept") << Polyline{{0, 0}, {10, 0}, {10, 10}} << Polyline{{0, 0}, {10, 0}, {10, 10}};
}

void TestGeometry::simplify()
{
    QFETCH(Polyline, input);
    QFETCH(Polyline, expected);
    QCOMPARE(simplifyPolyline(input), expected);
}

void TestGeometry::routes_data()
{
    QTest::addColumn<QPointF>("from");
    QTest::addColumn<QPointF>("to");
    QTest::addColumn<QList<QRectF>>("obstacles");
    QTest::addColumn<Polyline>("expected");

    QTest::newRow("straight") << QPointF(100, 50) << QPointF(200, 50) << QList<QRectF>{}
                              << Polyline{{100, 50}, {200, 50}};
    // Two bends, the vertical run half way between the pins.
    QTest::newRow("step down") << QPointF(100, 50) << QPointF(200, 90) << QList<QRectF>{}
                               << Polyline{{100, 50}, {150, 50}, {150, 90}, {200, 90}};
    // A box sits between the pins on their line: the wire goes round it closely, above it (the
    // shorter side).
    QTest::newRow("around a box") << QPointF(100, 50) << QPointF(300, 50)
                                  << QList<QRectF>{QRectF(180, 40, 40, 60)}
                                  << Polyline{{100, 50}, {170, 50}, {170, 30}, {230, 30}, {230, 50}, {300, 50}};
    // Feedback: the input lies left of the output, so the wire leaves right, loops below both
    // boxes and enters from the left.
    QTest::newRow("feedback loop") << QPointF(200, 50) << QPointF(100, 50)
                                   << QList<QRectF>{QRectF(100, 30, 100, 40)}
                                   << Polyline{{200, 50}, {210, 50}, {210, 80}, {90, 80}, {90, 50}, {100, 50}};
}

void TestGeometry::routes()
{
    QFETCH(QPointF, from);
    QFETCH(QPointF, to);
    QFETCH(QList<QRectF>, obstacles);
    QFETCH(Polyline, expected);
    QCOMPARE(routeOrthogonal({from, to, obstacles, 10}), expected);
}

void TestGeometry::routesAreOrthogonalAndAvoidObstacles_data()
{
    QTest::addColumn<QPointF>("from");
    QTest::addColumn<QPointF>("to");
    QTest::addColumn<QList<QRectF>>("obstacles");
    const QList<QRectF> wall{QRectF(150, 0, 20, 200), QRectF(230, 60, 40, 40)};
    QTest::newRow("wall") << QPointF(100, 100) << QPointF(300, 120) << wall;
    QTest::newRow("backwards round a wall") << QPointF(300, 80) << QPointF(100, 140) << wall;
    QTest::newRow("stacked boxes")
        << QPointF(60, 20) << QPointF(400, 300)
        << QList<QRectF>{QRectF(0, 0, 60, 40), QRectF(100, 0, 60, 400), QRectF(200, 100, 60, 60),
                         QRectF(400, 280, 60, 40)};
}

void TestGeometry::routesAreOrthogonalAndAvoidObstacles()
{
    QFETCH(QPointF, from);
    QFETCH(QPointF, to);
    QFETCH(QList<QRectF>, obstacles);
    const Polyline route = routeOrthogonal({from, to, obstacles, 10});

    QCOMPARE(route.first(), from);
    QCOMPARE(route.last(), to);
    QVERIFY(route.at(1).x() > from.x()); // leaves the output to the right
    QVERIFY(route.at(route.size() - 2).x() < to.x()); // enters the input from the left
    for (int i = 1; i < route.size(); ++i) {
        const QPointF a = route.at(i - 1);
        const QPointF b = route.at(i);
        QVERIFY2(a.x() == b.x() || a.y() == b.y(), "segment not orthogonal");
        const QRectF segment = QRectF(a, b).normalized().adjusted(-0.01, -0.01, 0.01, 0.01);
        for (const QRectF &obstacle : obstacles)
            QVERIFY2(!segment.intersects(obstacle.adjusted(1, 1, -1, -1)), "segment crosses a box");
    }
}

QTEST_GUILESS_MAIN(TestGeometry)
#include "tst_geometry.moc"
