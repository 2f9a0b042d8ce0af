// Graphical bodies open through the editor registry (DESIGN.md): the document area asks it by
// editor language and wires what it gets (grid, online instance, completion, opening actions),
// the Insert, Edit and View menus show the current editor's commands and the status bar its
// zoom, build messages on elements mark them. A test language (the boxes of
// tests/editors/boxdiagram.h, registered for FBD in place of the real editor) stands in for any
// language.
#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/messagespane.h"
#include "editors/common/diagrameditor.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/common/editorregistry.h"
#include "editors/standardeditors.h"
#include "editors/ld/ldeditor.h"
#include "editors/sfc/sfceditor.h"
#include "model/projectmodel.h"
#include "tests/editors/boxdiagram.h"

#include <QAction>
#include <QApplication>
#include <QHash>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QWheelEvent>
#include <QTest>
#include <QToolBar>

using namespace iec;
using namespace iec::app;
using model::BodyRef;

namespace {

class BoxEditor : public editors::DiagramEditor
{
    Q_OBJECT

public:
    BoxEditor(model::ProjectModel &model, const BodyRef &ref, QUndoStack *stack)
        : DiagramEditor(model, ref, stack, std::make_unique<tests::BoxPolicy>())
    {
        const ActionSpec specs[] = {
            {"boxAdd", QT_TR_NOOP("Add Box"), "", ActionGroup::Insert, true, true, [] {}},
            {"boxOpen", QT_TR_NOOP("Open Action"), "", ActionGroup::Element, false, false,
                [this] { Q_EMIT openPartRequested(bodyRef().pou, BodyRef::Part::Action, QStringLiteral("Fill")); }},
        };
        addActionTable(specs);
    }
};

model::Pou pouIn(model::BodyLanguage language, const QString &name)
{
    model::Pou pou;
    pou.name = name;
    pou.kind = model::PouKind::Program;
    pou.bodies.push_back(model::Body::withLanguage(language));
    return pou;
}

model::Project project()
{
    model::Project project;
    model::Pou boxes = pouIn(model::BodyLanguage::FBD, QStringLiteral("Boxes"));
    model::Element a = tests::inVariableAt(0, 0, QStringLiteral("A"));
    model::header(a).localId = 7;
    boxes.bodies.front().elements()->push_back(a);
    model::Element b = tests::outVariableAt(100, 0, QStringLiteral("B")); // B is not declared
    model::header(b).localId = 8;
    std::get<model::OutVariable>(b).connectionPointIn->connections.push_back({.refLocalId = 7});
    boxes.bodies.front().elements()->push_back(b);
    model::PouPart fill;
    fill.name = QStringLiteral("Fill");
    fill.body = model::Body::withLanguage(model::BodyLanguage::ST);
    boxes.actions.push_back(fill);
    project.types.pous.push_back(boxes);
    project.types.pous.push_back(pouIn(model::BodyLanguage::LD, QStringLiteral("Ladder")));
    // CODESYS keeps a CFC diagram in the addData of an empty ST body.
    model::Pou cfc = pouIn(model::BodyLanguage::ST, QStringLiteral("Flow"));
    cfc.bodies.front().addData.push_back(
        {QStringLiteral("http://www.3s-software.com/plcopenxml/cfc"), QStringLiteral("handle"), QStringLiteral("<CFC/>")});
    project.types.pous.push_back(cfc);
    project.types.pous.push_back(pouIn(model::BodyLanguage::SFC, QStringLiteral("Chart")));
    project.types.pous.push_back(pouIn(model::BodyLanguage::ST, QStringLiteral("Text")));
    return project;
}

BodyRef bodyOf(MainWindow &window, const char *pou)
{
    return {window.projectModel().project().findPou(QLatin1String(pou))->id, BodyRef::Part::Pou, {}};
}

} // namespace

class TestDiagramDocuments : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        // The stand-in replaces the real FBD editor: registered after the standard editors (the
        // window registers them once, and later calls change nothing).
        editors::registerStandardEditors();
        editors::EditorRegistry::instance().add({editors::EditorLanguage::FBD,
            [](model::ProjectModel &model, const BodyRef &ref, QUndoStack *stack) -> editors::DiagramEditor * {
                return new BoxEditor(model, ref, stack);
            },
            [] { return std::unique_ptr<editors::DiagramPolicy>(std::make_unique<tests::BoxPolicy>()); }});
    }

    void bodiesOpenInTheEditorOfTheirLanguage()
    {
        MainWindow window;
        window.projectModel().reset(project());
        DocumentArea &documents = window.documents();
        documents.setGridSize(20);
        const BodyRef boxes = bodyOf(window, "Boxes");
        QVERIFY(documents.openBody(boxes));
        editors::DiagramEditor *editor = documents.diagramEditorFor(boxes);
        QVERIFY(qobject_cast<BoxEditor *>(editor));
        QCOMPARE(documents.currentDiagramEditor(), editor);
        QCOMPARE(editor->view()->gridSize(), 20);
        QCOMPARE(editor->scene()->gridSize(), 20);
        QCOMPARE(editor->onlineInstance(), QStringLiteral("Boxes"));
        QVERIFY(editor->completionProvider());
        QVERIFY(editor->scene()->itemFor(7));
        // The settings' grid reaches open editors too.
        documents.setGridSize(5);
        QCOMPARE(editor->view()->gridSize(), 5);
        // An editor's request to open an action opens it.
        QVERIFY(editor->trigger(QStringLiteral("boxOpen")));
        QCOMPARE(documents.currentBody(), (BodyRef {boxes.pou, BodyRef::Part::Action, QStringLiteral("Fill")}));
        // LD and SFC through the registry too.
        QVERIFY(qobject_cast<editors::ld::LdEditor *>(
            qobject_cast<QWidget *>(documents.openBody(bodyOf(window, "Ladder")))->findChild<editors::DiagramEditor *>()));
        QVERIFY(qobject_cast<editors::sfc::SfcEditor *>(
            qobject_cast<QWidget *>(documents.openBody(bodyOf(window, "Chart")))->findChild<editors::DiagramEditor *>()));
    }

    void codesysCfcOpensInTheCfcEditor()
    {
        // CODESYS's CFC (an empty ST body with the chart in addData) is a diagram, not ST text.
        MainWindow window;
        window.projectModel().reset(project());
        const BodyRef ref = bodyOf(window, "Flow");
        QVERIFY(window.documents().openBody(ref));
        editors::DiagramEditor *editor = window.documents().diagramEditorFor(ref);
        QVERIFY(editor);
        QVERIFY(editor->action(QStringLiteral("cfcOrderDataFlow")));
        QVERIFY(!window.documents().textEditorFor(ref));
    }

    void theMenusFollowTheCurrentDiagramEditor_data()
    {
        // Every diagram editor's table reaches the window's menus through the base: its Insert
        // commands the Insert menu, its element commands the Edit menu, its view commands the
        // View menu (issue 13: the SFC commands were missing from Edit, the zoom from View).
        QTest::addColumn<QString>("pou");
        QTest::addColumn<QString>("menu");
        QTest::addColumn<QStringList>("actions");
        const QStringList view {QStringLiteral("zoomIn"), QStringLiteral("zoomOut"), QStringLiteral("zoomReset"),
            QStringLiteral("fitToWindow"), QStringLiteral("exportPicture")};
        QTest::newRow("boxes insert") << "Boxes" << "insertMenu" << QStringList {QStringLiteral("boxAdd")};
        QTest::newRow("boxes edit") << "Boxes" << "editMenu" << QStringList {QStringLiteral("boxOpen")};
        QTest::newRow("boxes view") << "Boxes" << "viewMenu" << view;
        QTest::newRow("ladder view") << "Ladder" << "viewMenu" << view;
        QTest::newRow("chart insert") << "Chart" << "insertMenu"
                                      << QStringList {QStringLiteral("sfcStepAfter"), QStringLiteral("sfcAltRight"),
                                             QStringLiteral("sfcParRight"), QStringLiteral("sfcJump")};
        QTest::newRow("chart edit") << "Chart" << "editMenu"
                                    << QStringList {QStringLiteral("sfcProperties"), QStringLiteral("sfcActions"),
                                           QStringLiteral("sfcCondition"), QStringLiteral("sfcPriority"),
                                           QStringLiteral("sfcArrange")};
        QTest::newRow("chart view") << "Chart" << "viewMenu" << view;
    }

    void theMenusFollowTheCurrentDiagramEditor()
    {
        QFETCH(QString, pou);
        QFETCH(QString, menu);
        QFETCH(QStringList, actions);
        MainWindow window;
        window.projectModel().reset(project());
        window.show();
        auto *menuWidget = window.menuBar()->findChild<QMenu *>(menu);
        QVERIFY(menuWidget);
        window.documents().openBody(bodyOf(window, qPrintable(pou)));
        editors::DiagramEditor *editor = window.documents().currentDiagramEditor();
        QVERIFY(editor);
        QList<QAction *> shown;
        for (const QString &id : std::as_const(actions)) {
            QAction *action = editor->action(id);
            QVERIFY2(action, qPrintable(id));
            QVERIFY2(menuWidget->actions().contains(action), qPrintable(id));
            shown << action;
        }
        // Cut, Copy, Paste and Delete are the window's own entries (EditActions), not twice.
        for (QAction *action : editor->actionsIn(editors::DiagramEditor::ActionGroup::Edit))
            QVERIFY2(!menuWidget->actions().contains(action), qPrintable(action->objectName()));
        // Another document in front takes them out again: ST text.
        window.documents().openBody(bodyOf(window, "Text"));
        QVERIFY(!window.documents().currentDiagramEditor());
        for (QAction *action : std::as_const(shown))
            QVERIFY2(!menuWidget->actions().contains(action), qPrintable(action->objectName()));
    }

    void theStatusBarShowsTheCurrentDiagramsZoom_data()
    {
        QTest::addColumn<QString>("pou");
        QTest::newRow("boxes") << "Boxes";
        QTest::newRow("ladder") << "Ladder";
        QTest::newRow("chart") << "Chart";
    }

    void theStatusBarShowsTheCurrentDiagramsZoom()
    {
        // Issue 13: the View menu had no zoom entries and the zoom was nowhere to be seen. The
        // status bar shows the current diagram's zoom, whether the View menu, a key or the wheel
        // changed it.
        QFETCH(QString, pou);
        MainWindow window;
        window.projectModel().reset(project());
        window.show();
        auto *label = window.statusBar()->findChild<QLabel *>(QStringLiteral("zoomLabel"));
        QVERIFY(label);
        QVERIFY(!label->isVisible());
        window.documents().openBody(bodyOf(window, qPrintable(pou)));
        editors::DiagramEditor *editor = window.documents().currentDiagramEditor();
        QVERIFY(editor);
        QVERIFY(label->isVisible());
        QCOMPARE(label->text(), QStringLiteral("Zoom: 100 %"));
        auto *viewMenu = window.menuBar()->findChild<QMenu *>(QStringLiteral("viewMenu"));
        const auto viewEntry = [&](const char *id) {
            QAction *action = editor->action(QString::fromLatin1(id));
            return viewMenu->actions().contains(action) ? action : nullptr;
        };
        QVERIFY(viewEntry("zoomIn"));
        viewEntry("zoomIn")->trigger();
        QCOMPARE(label->text(), QStringLiteral("Zoom: %1 %").arg(editor->zoomPercent()));
        QVERIFY(editor->zoomPercent() > 100);
        viewEntry("zoomReset")->trigger();
        QCOMPARE(editor->zoomPercent(), 100);
        QCOMPARE(label->text(), QStringLiteral("Zoom: 100 %"));
        // Ctrl+wheel and the keys, in the view.
        QWidget *viewport = editor->view()->viewport();
        const QPointF at(viewport->width() / 2.0, viewport->height() / 2.0);
        QWheelEvent wheel(at, viewport->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::ControlModifier,
            Qt::NoScrollPhase, false);
        QApplication::sendEvent(viewport, &wheel);
        QVERIFY(editor->zoomPercent() < 100);
        QCOMPARE(label->text(), QStringLiteral("Zoom: %1 %").arg(editor->zoomPercent()));
        editor->view()->setFocus();
        editor->resetZoom();
        viewEntry("zoomOut")->trigger();
        viewEntry("fitToWindow")->trigger();
        QCOMPARE(label->text(), QStringLiteral("Zoom: %1 %").arg(editor->zoomPercent()));
        // No diagram in front: no zoom to show.
        window.documents().openBody(bodyOf(window, "Text"));
        QVERIFY(!label->isVisible());
    }

    void theToolBarKeepsItsViewCommandsInSightAt1600Pixels_data()
    {
        // Issue 13: at 1600 px Fit to Window, Arrange Chart and Export went into the tool bar's
        // overflow menu, beside the project and library docks.
        QTest::addColumn<QString>("pou");
        QTest::addColumn<QStringList>("actions");
        const QStringList view {QStringLiteral("zoomIn"), QStringLiteral("zoomOut"), QStringLiteral("fitToWindow"),
            QStringLiteral("exportPicture")};
        QTest::newRow("chart") << "Chart" << view + QStringList {QStringLiteral("sfcArrange"), QStringLiteral("sfcDelete")};
    }

    void theToolBarKeepsItsViewCommandsInSightAt1600Pixels()
    {
        QFETCH(QString, pou);
        QFETCH(QStringList, actions);
        MainWindow window;
        window.projectModel().reset(project());
        window.resize(1600, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.documents().openBody(bodyOf(window, qPrintable(pou)));
        editors::DiagramEditor *editor = window.documents().currentDiagramEditor();
        QVERIFY(editor);
        QCoreApplication::processEvents();
        auto *bar = editor->findChild<QToolBar *>(QStringLiteral("diagramToolBar"));
        QVERIFY(bar);
        for (const QString &id : std::as_const(actions)) {
            QWidget *button = bar->widgetForAction(editor->action(id));
            QVERIFY2(button, qPrintable(id));
            QVERIFY2(button->isVisible(), qPrintable(id + QStringLiteral(" is in the overflow")));
        }
    }

    void noWindowShortcutIsAlsoTheDiagramEditors_data()
    {
        // Qt runs neither of two actions on one key: the window's Print Documentation and the
        // diagram editors' Print… both had Ctrl+P, so Ctrl+P did nothing in a diagram.
        QTest::addColumn<QString>("pou");
        QTest::newRow("ladder") << "Ladder";
        QTest::newRow("chart") << "Chart";
        QTest::newRow("cfc") << "Flow";
    }

    void noWindowShortcutIsAlsoTheDiagramEditors()
    {
        QFETCH(QString, pou);
        MainWindow window;
        window.projectModel().reset(project());
        window.show();
        window.documents().openBody(bodyOf(window, qPrintable(pou)));
        editors::DiagramEditor *editor = window.documents().currentDiagramEditor();
        QVERIFY(editor);
        const auto ownedByEditor = [editor](const QObject *object) {
            for (; object; object = object->parent())
                if (object == editor)
                    return true;
            return false;
        };
        QHash<QKeySequence, QString> windowKeys;
        for (QAction *action : window.findChildren<QAction *>()) {
            if (ownedByEditor(action) || !action->isEnabled()
                || (action->shortcutContext() != Qt::WindowShortcut && action->shortcutContext() != Qt::ApplicationShortcut))
                continue;
            for (const QKeySequence &key : action->shortcuts())
                windowKeys.insert(key, action->objectName() + QLatin1Char(' ') + action->text());
        }
        QVERIFY(windowKeys.contains(QKeySequence(QStringLiteral("Ctrl+Shift+P"))));
        int checked = 0;
        for (QAction *action : editor->findChildren<QAction *>()) {
            for (const QKeySequence &key : action->shortcuts()) {
                ++checked;
                QVERIFY2(!windowKeys.contains(key), qPrintable(QStringLiteral("%1 (%2) is also the window's %3")
                                                                    .arg(action->objectName(), key.toString(), windowKeys.value(key))));
            }
        }
        QVERIFY(checked > 5);
    }

    void buildMessagesMarkTheirElements()
    {
        MainWindow window;
        // Only the boxes: the empty chart's own error (no initial step) would stop the build first.
        model::Project boxesOnly = project();
        std::erase_if(boxesOnly.types.pous, [](const model::Pou &pou) { return pou.name != QLatin1String("Boxes"); });
        window.projectModel().reset(boxesOnly);
        const BodyRef boxes = bodyOf(window, "Boxes");
        window.documents().openBody(boxes);
        editors::DiagramEditor *editor = window.documents().diagramEditorFor(boxes);
        QVERIFY(!window.buildController().build());
        bool reported = false;
        QStringList messages;
        for (const Message &message : window.buildController().lastMessages()) {
            reported |= message.pouName == QLatin1String("Boxes") && message.localId == quint64(8);
            messages << message.pouName + QStringLiteral(": ") + message.text;
        }
        QVERIFY2(reported, qPrintable(messages.join(QLatin1Char('\n'))));
        QVERIFY2(editor->scene()->itemFor(8)->diagnosticMessage().contains(QStringLiteral("'B'")),
            qPrintable(editor->scene()->itemFor(8)->diagnosticMessage()));
        QVERIFY(editor->scene()->itemFor(7)->diagnosticMessage().isEmpty());
        // A double-click on the message selects the element.
        editor->select({});
        for (const Message &message : window.buildController().lastMessages())
            if (message.localId == quint64(8))
                window.buildController().openLocation(message);
        QCOMPARE(editor->selection(), QList<quint64> {8});
    }
};

QTEST_MAIN(TestDiagramDocuments)
#include "tst_diagramdocuments.moc"
