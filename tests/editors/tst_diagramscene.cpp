// The shared diagram scene: items from (model, body) through a policy, rebuilt on model signals,
// the selection as localIds across rebuilds, double-clicks reported by localId, export.
#include "editors/common/diagramexport.h"
#include "editors/common/diagramitem.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "model/body.h"
#include "model/projectmodel.h"

#include <QDir>
#include <QGraphicsSceneMouseEvent>
#include <QPainter>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace iec;
using namespace iec::editors;

namespace {

class BoxItem : public DiagramItem
{
public:
    explicit BoxItem(const model::Element &element)
        : DiagramItem(model::header(element).localId)
        , m_rect(model::header(element).position.x, model::header(element).position.y, 40, 20)
    {
    }
    QRectF boundingRect() const override { return m_rect; }
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *) override { painter->drawRect(m_rect); }

private:
    QRectF m_rect;
};

class BoxPolicy : public DiagramPolicy
{
public:
    void populate(QGraphicsScene &scene, const std::vector<model::Element> &elements) override
    {
        for (const model::Element &element : elements)
            scene.addItem(new BoxItem(element));
    }
};

model::Element commentAt(double x, double y)
{
    model::Comment comment;
    comment.position = {x, y};
    return comment;
}

} // namespace

class TestDiagramScene : public QObject
{
    Q_OBJECT

private:
    model::ProjectModel m_model;
    model::BodyRef m_ref;

private Q_SLOTS:
    void init()
    {
        model::Project project;
        model::Pou pou;
        pou.name = QStringLiteral("P");
        pou.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::FBD));
        project.types.pous.push_back(pou);
        m_model.reset(project);
        m_ref = {m_model.project().types.pous.front().id};
        m_model.insertElement(m_ref, commentAt(0, 0));
        m_model.insertElement(m_ref, commentAt(100, 0));
    }

    void itemsFollowTheModel()
    {
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        QCOMPARE(scene.diagramItems().size(), 2);
        QSignalSpy rebuilt(&scene, &DiagramScene::rebuilt);
        const quint64 added = m_model.insertElement(m_ref, commentAt(200, 0));
        m_model.moveElement(m_ref, added, {300, 0});
        QCOMPARE(rebuilt.count(), 0); // collected ...
        QVERIFY(rebuilt.wait(1000) || rebuilt.count() == 1); // ... and rebuilt once
        QCOMPARE(rebuilt.count(), 1);
        QCOMPARE(scene.diagramItems().size(), 3);
        QCOMPARE(scene.itemFor(added)->boundingRect().left(), 300.0);
        // Another body's changes leave the scene alone.
        model::Pou other;
        other.name = QStringLiteral("Q");
        other.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::FBD));
        const model::PouId otherId = m_model.addPou(other);
        m_model.insertElement({otherId}, commentAt(0, 0));
        QCoreApplication::processEvents();
        QCOMPARE(rebuilt.count(), 1);
    }

    void selectionIsLocalIdsAndSurvivesRebuilds()
    {
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        scene.selectLocalIds({2});
        QCOMPARE(scene.selectedLocalIds(), QList<quint64> {2});
        m_model.moveElement(m_ref, 1, {0, 50});
        scene.rebuildIfDirty();
        QCOMPARE(scene.selectedLocalIds(), QList<quint64> {2});
        m_model.removeElement(m_ref, 2);
        scene.rebuildIfDirty();
        QVERIFY(scene.selectedLocalIds().isEmpty());
    }

    void doubleClickAndShiftClickReportLocalIds()
    {
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        DiagramView view;
        view.setScene(&scene);
        view.resize(400, 200);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QSignalSpy doubleClicked(&scene, &DiagramScene::elementDoubleClicked);
        QSignalSpy shiftClicked(&scene, &DiagramScene::elementShiftClicked);
        const QPoint onSecond = view.mapFromScene(QPointF(110, 10));
        QTest::mouseDClick(view.viewport(), Qt::LeftButton, {}, onSecond);
        QCOMPARE(doubleClicked.count(), 1);
        QCOMPARE(doubleClicked.front().at(0).value<quint64>(), quint64(2));
        QTest::mouseClick(view.viewport(), Qt::LeftButton, Qt::ShiftModifier, view.mapFromScene(QPointF(10, 10)));
        QCOMPARE(shiftClicked.count(), 1);
        QCOMPARE(shiftClicked.front().at(0).value<quint64>(), quint64(1));
    }

    void fitToWindowShowsEverything()
    {
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        m_model.insertElement(m_ref, commentAt(2000, 1000));
        scene.rebuild();
        DiagramView view;
        view.setScene(&scene);
        view.resize(400, 300);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.fitToWindow();
        // The drawing (2060 wide with its margin) does not fit 400 pixels even at the smallest step.
        QCOMPARE(view.zoom(), 0.25);
        view.setGridSize(10);
        QCOMPARE(view.gridSize(), 10);
    }

    void fitToWindowOfAHiddenViewUsesItsSize()
    {
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        DiagramView view;
        view.setScene(&scene);
        view.resize(400, 300);
        QVERIFY(!view.isVisible());
        view.fitToWindow();
        // The two boxes with their margin are 160 x 40: the width decides, not the size the
        // viewport of a view never shown has.
        const QSize inside = view.contentsRect().size();
        QVERIFY(inside.width() > 390);
        QCOMPARE(view.zoom(), inside.width() / 160.0);
    }

    void exportsPictures()
    {
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        scene.selectLocalIds({1});
        QTemporaryDir dir;
        for (const char *suffix : {"svg", "png", "pdf"}) {
            const QString path = dir.filePath(QStringLiteral("d.") + QLatin1String(suffix));
            QCOMPARE(exportScene(scene, path), QString());
            QVERIFY(QFileInfo(path).size() > 100);
        }
        QCOMPARE(scene.selectedLocalIds(), QList<quint64> {1}); // the selection is back
        QVERIFY(exportScene(scene, dir.filePath(QStringLiteral("d.bmpx"))).contains(QStringLiteral("bmpx")));
    }
};

QTEST_MAIN(TestDiagramScene)
#include "tst_diagramscene.moc"
