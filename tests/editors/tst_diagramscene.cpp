// The shared diagram scene: items from (model, body) through a policy, brought up to date after
// each command (incrementally when the policy can, with an index by localId), the selection as
// localIds across both, clicks reported by localId, drags and wires by mouse, export.
#include "editors/common/diagramexport.h"
#include "editors/common/diagramitem.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "model/body.h"
#include "model/projectmodel.h"
#include "model/undo/bodyelementscommand.h"
#include "tests/editors/boxdiagram.h"

#include <QDir>
#include <QGraphicsSceneMouseEvent>
#include <QPainter>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace iec;
using namespace iec::editors;

using tests::BoxPolicy;
using tests::commentAt;

namespace {

// In-variable A (localId 1, an output pin at its right) and out-variable B (localId 2, an input
// pin at its left), 60 apart.
std::vector<model::Element> twoBoxes()
{
    model::Element a = tests::inVariableAt(0, 0, QStringLiteral("A"));
    model::header(a).localId = 1;
    model::Element b = tests::outVariableAt(100, 0, QStringLiteral("B"));
    model::header(b).localId = 2;
    return {a, b};
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

    void changesAreCollectedAndFollowedIncrementally_data()
    {
        // A command made of model calls on the body of elements 1 and 2; the changes the policy is
        // then given (localIds; "-" none) and whether it was asked at all.
        QTest::addColumn<QString>("command");
        QTest::addColumn<QString>("inserted");
        QTest::addColumn<QString>("removed");
        QTest::addColumn<QString>("changed");
        QTest::newRow("insert") << "insert" << "3" << "-" << "-";
        QTest::newRow("move") << "move 1" << "-" << "-" << "1";
        QTest::newRow("insert then move it") << "insert, move 3" << "3" << "-" << "-";
        QTest::newRow("insert then remove it") << "insert, remove 3" << "-" << "-" << "-";
        QTest::newRow("move then remove") << "move 1, remove 1" << "-" << "1" << "-";
        QTest::newRow("replace all") << "replace" << "7" << "1" << "2";
        QTest::newRow("connect") << "connect" << "-" << "-" << "2";
    }

    void changesAreCollectedAndFollowedIncrementally()
    {
        QFETCH(QString, command);
        QFETCH(QString, inserted);
        QFETCH(QString, removed);
        QFETCH(QString, changed);
        QVERIFY(m_model.replaceElements(m_ref, twoBoxes()));
        BoxPolicy policy;
        policy.followsChanges = true;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        scene.selectLocalIds({1, 2});
        const DiagramItem *first = scene.itemFor(1);
        QSignalSpy updated(&scene, &DiagramScene::updated);
        QSignalSpy rebuilt(&scene, &DiagramScene::rebuilt);
        for (const QString &step : command.split(QStringLiteral(", "))) {
            const QStringList words = step.split(QLatin1Char(' '));
            if (words[0] == QLatin1String("insert"))
                QCOMPARE(m_model.insertElement(m_ref, commentAt(200, 0)), quint64(3));
            else if (words[0] == QLatin1String("move"))
                QVERIFY(m_model.moveElement(m_ref, words[1].toULongLong(), {5, 50}));
            else if (words[0] == QLatin1String("remove"))
                QVERIFY(m_model.removeElement(m_ref, words[1].toULongLong()));
            else if (words[0] == QLatin1String("connect"))
                QVERIFY(m_model.connect(m_ref, 2, 0, {.refLocalId = 1}));
            else if (words[0] == QLatin1String("replace")) {
                model::Element seven = commentAt(300, 0);
                model::header(seven).localId = 7;
                model::Element two = tests::outVariableAt(100, 60, QStringLiteral("B"));
                model::header(two).localId = 2;
                QVERIFY(m_model.replaceElements(m_ref, {two, seven}));
            }
        }
        QCOMPARE(updated.count() + rebuilt.count(), 0); // collected until the command is done
        scene.rebuildIfDirty();
        QCOMPARE(rebuilt.count(), 0);
        const auto ids = [](const QSet<quint64> &set) {
            QList<quint64> list(set.begin(), set.end());
            std::sort(list.begin(), list.end());
            QStringList words;
            for (quint64 id : list)
                words << QString::number(id);
            return words.isEmpty() ? QStringLiteral("-") : words.join(QLatin1Char(' '));
        };
        if (inserted == QLatin1String("-") && removed == QLatin1String("-") && changed == QLatin1String("-")) {
            QCOMPARE(policy.updates, 0);
            QCOMPARE(updated.count(), 0);
        } else {
            QCOMPARE(policy.updates, 1);
            QCOMPARE(updated.count(), 1);
            QCOMPARE(ids(policy.changes.front().inserted), inserted);
            QCOMPARE(ids(policy.changes.front().removed), removed);
            QCOMPARE(ids(policy.changes.front().changed), changed);
        }
        QCOMPARE(policy.populated, 1); // never rebuilt
        // The index and the items follow the model; untouched items are the same objects.
        const std::vector<model::Element> &now = *m_model.body(m_ref)->elements();
        QCOMPARE(scene.diagramItems().size(), qsizetype(now.size()));
        for (const model::Element &element : now)
            QVERIFY(scene.itemFor(model::header(element).localId));
        if (!policy.changes.empty() && !policy.changes.front().changed.contains(1) && !policy.changes.front().removed.contains(1))
            QCOMPARE(scene.itemFor(1), first);
        // The selection survives, minus what is gone.
        QList<quint64> stillThere;
        for (quint64 id : {quint64(1), quint64(2)})
            if (scene.itemFor(id))
                stillThere << id;
        QCOMPARE(scene.selectedLocalIds(), stillThere);
    }

    void aPolicyThatDeclinesGetsARebuild()
    {
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        QUndoStack stack;
        QSignalSpy rebuilt(&scene, &DiagramScene::rebuilt);
        stack.push(new model::SetBodyElementsCommand(m_model, m_ref, {commentAt(5, 5)}, QStringLiteral("x")));
        scene.rebuildIfDirty();
        QCOMPARE(rebuilt.count(), 1);
        QCOMPARE(policy.populated, 2);
        QCOMPARE(scene.diagramItems().size(), 1);
        // A reset of the project always rebuilds, even for a policy that follows changes.
        policy.followsChanges = true;
        m_model.reset(m_model.project());
        scene.rebuildIfDirty();
        QCOMPARE(rebuilt.count(), 2);
        QCOMPARE(policy.updates, 0);
    }

    void theIndexForgetsDeletedItems()
    {
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        QVERIFY(scene.itemFor(1));
        delete scene.itemFor(1);
        QVERIFY(!scene.itemFor(1));
        scene.removeElementItem(2);
        QVERIFY(!scene.itemFor(2));
        QVERIFY(scene.diagramItems().isEmpty());
    }

    void pinsAreFoundNearAPoint()
    {
        QVERIFY(m_model.replaceElements(m_ref, twoBoxes()));
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        const auto out = scene.pinAt(QPointF(42, 11));
        QVERIFY(out);
        QCOMPARE(out->item->localId(), quint64(1));
        QCOMPARE(out->pin.direction, Pin::Direction::Out);
        const auto in = scene.pinAt(QPointF(97, 8));
        QVERIFY(in);
        QCOMPARE(in->item->localId(), quint64(2));
        QCOMPARE(in->pin.inputIndex, 0);
        QVERIFY(!scene.pinAt(QPointF(70, 10)));
    }

    void dragMovesTheSelectionOnTheGrid()
    {
        QVERIFY(m_model.replaceElements(m_ref, twoBoxes()));
        BoxPolicy policy;
        policy.mouseEditing = true;
        DiagramScene scene(m_model, m_ref, policy);
        scene.setGridSize(10);
        scene.rebuild();
        DiagramView view;
        view.setScene(&scene);
        view.resize(400, 200);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        scene.selectLocalIds({1, 2});
        QSignalSpy moved(&scene, &DiagramScene::elementsMoved);
        const QPoint from = view.mapFromScene(QPointF(20, 5));
        QTest::mousePress(view.viewport(), Qt::LeftButton, {}, from);
        QTest::mouseMove(view.viewport(), view.mapFromScene(QPointF(30, 20)));
        QTest::mouseMove(view.viewport(), view.mapFromScene(QPointF(44, 38)));
        QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, view.mapFromScene(QPointF(44, 38)));
        QCOMPARE(moved.count(), 1);
        QCOMPARE(moved.front().at(0).value<QList<quint64>>(), (QList<quint64> {1, 2}));
        // Moved by (24, 33), snapped: the pressed box lands on (20, 30), the other keeps its offset.
        QCOMPARE(moved.front().at(1).value<QList<QPointF>>(), (QList<QPointF> {QPointF(20, 30), QPointF(120, 30)}));
        QCOMPARE(scene.selectedLocalIds(), (QList<quint64> {1, 2}));
        // A box the policy does not let move stays.
        policy.mouseEditing = false;
        QTest::mousePress(view.viewport(), Qt::LeftButton, {}, from);
        QTest::mouseMove(view.viewport(), view.mapFromScene(QPointF(60, 60)));
        QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, view.mapFromScene(QPointF(60, 60)));
        QCOMPARE(moved.count(), 1);
    }

    void wiresAreDrawnFromPinToPin()
    {
        QVERIFY(m_model.replaceElements(m_ref, twoBoxes()));
        BoxPolicy policy;
        policy.mouseEditing = true;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        DiagramView view;
        view.setScene(&scene);
        view.resize(400, 200);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QSignalSpy drawn(&scene, &DiagramScene::wireDrawn);
        // From the input back to the output: the wire still runs from the output.
        QTest::mousePress(view.viewport(), Qt::LeftButton, {}, view.mapFromScene(QPointF(100, 10)));
        QTest::mouseMove(view.viewport(), view.mapFromScene(QPointF(60, 12)));
        QCOMPARE(scene.items().size(), 3); // the rubber wire
        QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, view.mapFromScene(QPointF(41, 10)));
        QCOMPARE(scene.items().size(), 2);
        QCOMPARE(drawn.count(), 1);
        QCOMPARE(drawn.front().at(0).value<quint64>(), quint64(1));
        QCOMPARE(drawn.front().at(1).toString(), QString());
        QCOMPARE(drawn.front().at(2).value<quint64>(), quint64(2));
        QCOMPARE(drawn.front().at(3).toInt(), 0);
        // Ending nowhere near a pin draws nothing; neither does a scene that is only looked at.
        QTest::mousePress(view.viewport(), Qt::LeftButton, {}, view.mapFromScene(QPointF(40, 10)));
        QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, view.mapFromScene(QPointF(70, 70)));
        scene.setEditable(false);
        QTest::mousePress(view.viewport(), Qt::LeftButton, {}, view.mapFromScene(QPointF(40, 10)));
        QTest::mouseRelease(view.viewport(), Qt::LeftButton, {}, view.mapFromScene(QPointF(100, 10)));
        QCOMPARE(drawn.count(), 1);
    }

    void rightClickSelectsWhatItIsOn()
    {
        BoxPolicy policy;
        DiagramScene scene(m_model, m_ref, policy);
        scene.rebuild();
        DiagramView view;
        view.setScene(&scene);
        view.resize(400, 200);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QTest::mouseClick(view.viewport(), Qt::RightButton, {}, view.mapFromScene(QPointF(110, 10)));
        QCOMPARE(scene.selectedLocalIds(), QList<quint64> {2});
        scene.selectLocalIds({1, 2});
        QTest::mouseClick(view.viewport(), Qt::RightButton, {}, view.mapFromScene(QPointF(10, 10)));
        QCOMPARE(scene.selectedLocalIds(), (QList<quint64> {1, 2})); // part of the selection: kept
        QTest::mouseClick(view.viewport(), Qt::RightButton, {}, view.mapFromScene(QPointF(70, 100)));
        QCOMPARE(scene.selectedLocalIds(), (QList<quint64> {1, 2})); // nothing there: kept
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
