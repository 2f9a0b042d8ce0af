// The diagram editor base that every graphical editor shares, driven through a tiny language
// (boxdiagram.h) with an action table: the one edit path, the refusal while online for every
// action that changes the model (menu, trigger and shortcut), the context menu (right-click
// selection, enabling, Menu key at the selection), retranslation, drags and wires ending in one
// undo step, diagnostics on elements, the online overlay through a mapper.
#include "editors/common/diagrameditor.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/common/overlaymapper.h"
#include "editors/text/completion.h"
#include "interpreter/runtime/snapshot.h"
#include "model/projectmodel.h"
#include "tests/editors/boxdiagram.h"
#include "tests/editors/languageswitch.h"

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>

using namespace iec;
using namespace iec::editors;

namespace {

// Makes every box of a value "Main.<expression>" TRUE look active.
class BoxOverlay : public OverlayMapper
{
public:
    int applied = 0;
    QStringList names(const DiagramScene &scene, const QString &instance) const override
    {
        QStringList list;
        for (const model::Element &element : *scene.shownElements())
            if (const auto *in = std::get_if<model::InVariable>(&element))
                list << instance + QLatin1Char('.') + in->expression;
        return list;
    }
    void apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance) override
    {
        ++applied;
        for (const model::Element &element : *scene.shownElements())
            if (const auto *in = std::get_if<model::InVariable>(&element))
                scene.itemFor(in->localId)->setActive(snapshot.value(instance + QLatin1Char('.') + in->expression) == QLatin1String("TRUE"));
    }
    void clear(DiagramScene &scene) override
    {
        for (DiagramItem *item : scene.diagramItems())
            item->setActive(false);
    }
};

class BoxEditor : public DiagramEditor
{
    Q_OBJECT

public:
    int activated = 0;

    BoxEditor(model::ProjectModel &model, const model::BodyRef &ref, QUndoStack *stack)
        : DiagramEditor(model, ref, stack, std::make_unique<tests::BoxPolicy>())
    {
        auto overlay = std::make_unique<BoxOverlay>();
        m_overlay = overlay.get();
        setOverlayMapper(std::move(overlay));
        const auto any = [this] { return !selection().isEmpty(); };
        const ActionSpec specs[] = {
            {"boxAdd", QT_TR_NOOP("Add Box"), "Ctrl+B", ActionGroup::Insert, true, true, [this] { addBox(); }},
            {"boxRename", QT_TR_NOOP("Rename"), "", ActionGroup::Element, true, false, [this] { renameSelected(); }, any},
            {"boxDelete", QT_TR_NOOP("Delete"), "Del", ActionGroup::Edit, true, true, [this] { deleteSelected(); }, any},
            {"boxCount", QT_TR_NOOP("Count"), "Ctrl+K", ActionGroup::Edit, false, false,
                [this] { showMessage(QString::number(selection().size())); }},
        };
        addActionTable(specs);
    }
    BoxOverlay &overlay() const { return *m_overlay; }
    using DiagramEditor::policy;

protected:
    void activateElement(quint64, QPointF) override { ++activated; }

private:
    void addBox()
    {
        applyEdit(tr("Add box"), [](std::vector<model::Element> &elements) -> EditOutcome {
            quint64 next = 1;
            for (const model::Element &e : elements)
                next = std::max(next, model::header(e).localId + 1);
            model::Element box = tests::inVariableAt(double(next) * 60, 0, QStringLiteral("X%1").arg(next));
            model::header(box).localId = next;
            elements.push_back(box);
            return {{}, {next}};
        });
    }
    void renameSelected()
    {
        const std::vector<quint64> ids = selectedIds();
        applyEdit(tr("Rename"), [&](std::vector<model::Element> &elements) -> EditOutcome {
            for (model::Element &e : elements)
                if (auto *in = std::get_if<model::InVariable>(&e); in && std::ranges::count(ids, in->localId))
                    in->expression += QLatin1Char('_');
            return {{}, ids};
        });
    }
    void deleteSelected()
    {
        const std::vector<quint64> ids = selectedIds();
        applyEdit(tr("Delete"), [&](std::vector<model::Element> &elements) -> EditOutcome {
            if (ids.empty())
                return {QStringLiteral("Select a box first."), {}};
            if (ids.size() > 1)
                return {QStringLiteral("One at a time."), {}};
            std::erase_if(elements, [&](const model::Element &e) { return std::ranges::count(ids, model::header(e).localId) > 0; });
            return {};
        });
    }
    BoxOverlay *m_overlay = nullptr;
};

class TwoNames : public CompletionProvider
{
public:
    QList<CompletionItem> variables() const override
    {
        return {{QStringLiteral("Start"), CompletionItem::Kind::Variable, QStringLiteral("BOOL"), {}},
            {QStringLiteral("Stop"), CompletionItem::Kind::Variable, QStringLiteral("BOOL"), {}}};
    }
    QList<CompletionItem> members(const QString &) const override { return {}; }
    QList<CompletionItem> pous() const override { return {}; }
};

} // namespace

class TestDiagramEditor : public QObject
{
    Q_OBJECT

private:
    struct Fixture {
        model::ProjectModel model;
        QUndoStack stack;
        model::BodyRef ref;
        std::unique_ptr<BoxEditor> editor;

        Fixture()
        {
            model::Project project;
            model::Pou pou;
            pou.name = QStringLiteral("Main");
            pou.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::FBD));
            model::Element a = tests::inVariableAt(0, 0, QStringLiteral("A"));
            model::header(a).localId = 1;
            model::Element b = tests::outVariableAt(100, 0, QStringLiteral("B"));
            model::header(b).localId = 2;
            *pou.bodies.front().elements() = {a, b};
            project.types.pous.push_back(pou);
            model.reset(project);
            ref = {model.project().types.pous.front().id};
            editor = std::make_unique<BoxEditor>(model, ref, &stack);
            editor->setOnlineInstance(QStringLiteral("Main"));
            editor->resize(500, 300);
        }
        const std::vector<model::Element> &elements() const { return *model.body(ref)->elements(); }
        void goOnline()
        {
            interp::RuntimeSnapshot snapshot;
            snapshot.values.insert(QStringLiteral("Main.A"), QStringLiteral("TRUE"));
            editor->setOnlineSnapshot(&snapshot);
        }
    };

private Q_SLOTS:
    void aCommandIsOneUndoStepAndSelectsWhatItMade()
    {
        Fixture f;
        QVERIFY(f.editor->trigger(QStringLiteral("boxAdd")));
        QCOMPARE(f.stack.count(), 1);
        QCOMPARE(f.stack.undoText(), QStringLiteral("Add box"));
        QCOMPARE(f.elements().size(), std::size_t(3));
        QCOMPARE(f.editor->selection(), QList<quint64> {3});
        QVERIFY(f.editor->scene()->itemFor(3));
        // A refused edit shows why and pushes nothing.
        f.editor->select({1, 3});
        QVERIFY(!f.editor->trigger(QStringLiteral("boxDelete")));
        QCOMPARE(f.editor->lastMessage(), QStringLiteral("One at a time."));
        QCOMPARE(f.stack.count(), 1);
        // The message goes once the user looks elsewhere.
        f.editor->select({1});
        QCOMPARE(f.editor->lastMessage(), QString());
        // An edit that changes nothing pushes nothing either.
        QVERIFY(f.editor->applyEdit(QStringLiteral("nothing"), [](std::vector<model::Element> &) { return EditOutcome {}; }));
        QCOMPARE(f.stack.count(), 1);
        f.stack.undo();
        QCOMPARE(f.elements().size(), std::size_t(2));
        QVERIFY(!f.editor->trigger(QStringLiteral("noSuchAction")));
    }

    void aRefusalGoesOnceTheSituationChanged_data()
    {
        // Issue 13: refusals stayed on the message line after the situation they were about had
        // changed. Each row: a refusal, then a change that ends it.
        QTest::addColumn<QString>("change");
        QTest::newRow("another selection") << "select";
        QTest::newRow("offline again") << "offline";
        QTest::newRow("undo changes the diagram") << "undo";
        QTest::newRow("redo changes the diagram") << "redo";
        QTest::newRow("another language") << "language";
    }

    void aRefusalGoesOnceTheSituationChanged()
    {
        QFETCH(QString, change);
        Fixture f;
        f.editor->show();
        f.editor->select({1});
        QVERIFY(f.editor->trigger(QStringLiteral("boxRename")));
        if (change == QLatin1String("redo"))
            f.stack.undo();
        QCoreApplication::processEvents();
        // The refusal: online any edit, else deleting two boxes at once.
        const bool online = change == QLatin1String("offline");
        if (online)
            f.goOnline();
        f.editor->select({1, 2});
        QVERIFY(!f.editor->trigger(QStringLiteral("boxDelete")));
        QCOMPARE(f.editor->lastMessage(),
            online ? QStringLiteral("The diagram cannot be changed while online. Log out first (Online → Logout).")
                   : QStringLiteral("One at a time."));
        // A change that keeps the selection as it is, except "select".
        if (change == QLatin1String("select"))
            f.editor->select({2});
        else if (change == QLatin1String("offline"))
            f.editor->setOnlineSnapshot(nullptr);
        else if (change == QLatin1String("undo"))
            f.stack.undo();
        else if (change == QLatin1String("redo"))
            f.stack.redo();
        else {
            QEvent languageChange(QEvent::LanguageChange);
            QCoreApplication::sendEvent(f.editor.get(), &languageChange);
        }
        QCoreApplication::processEvents();
        if (change != QLatin1String("select"))
            QCOMPARE(f.editor->selection(), (QList<quint64> {1, 2}));
        QCOMPARE(f.editor->lastMessage(), QString());
    }

    void everyActionThatChangesTheModelIsRefusedOnline()
    {
        Fixture f;
        f.editor->show();
        f.editor->select({1});
        const std::vector<model::Element> before = f.elements();
        f.goOnline();
        const QString refusal = QStringLiteral("The diagram cannot be changed while online. Log out first (Online → Logout).");
        for (const char *id : {"boxAdd", "boxRename", "boxDelete"}) {
            QAction *action = f.editor->action(QString::fromLatin1(id));
            QVERIFY2(!action->isEnabled(), id);
            f.editor->showMessage(QString());
            QVERIFY2(!f.editor->trigger(QString::fromLatin1(id)), id);
            QCOMPARE(f.editor->lastMessage(), refusal);
        }
        // Their shortcuts say the same instead of doing nothing.
        for (const QKeySequence &keys : {QKeySequence(Qt::CTRL | Qt::Key_B), QKeySequence(Qt::Key_Delete)}) {
            f.editor->showMessage(QString());
            f.editor->view()->setFocus();
            QTest::keySequence(f.editor->view(), keys);
            QCOMPARE(f.editor->lastMessage(), refusal);
        }
        QVERIFY(f.elements() == before);
        QCOMPARE(f.stack.count(), 0);
        // What only looks stays usable.
        QVERIFY(f.editor->action(QStringLiteral("boxCount"))->isEnabled());
        QVERIFY(f.editor->trigger(QStringLiteral("boxCount")));
        QVERIFY(f.editor->action(QStringLiteral("zoomIn"))->isEnabled());
        // Offline again: everything works.
        f.editor->setOnlineSnapshot(nullptr);
        QVERIFY(f.editor->action(QStringLiteral("boxAdd"))->isEnabled());
        QVERIFY(f.editor->trigger(QStringLiteral("boxAdd")));
        QCOMPARE(f.stack.count(), 1);
    }

    void aGreyedShortcutSaysWhy()
    {
        Fixture f;
        f.editor->show();
        QApplication::setActiveWindow(f.editor.get());
        QVERIFY(QTest::qWaitForWindowActive(f.editor.get()));
        f.editor->select({});
        QVERIFY(!f.editor->action(QStringLiteral("boxDelete"))->isEnabled());
        f.editor->view()->setFocus();
        QTest::keyClick(f.editor->view(), Qt::Key_Delete);
        // The command ran and said why it does nothing.
        QCOMPARE(f.editor->lastMessage(), QStringLiteral("Select a box first."));
        QCOMPARE(f.stack.count(), 0);
        f.editor->select({1});
        QVERIFY(f.editor->action(QStringLiteral("boxDelete"))->isEnabled());
        QTest::keyClick(f.editor->view(), Qt::Key_Delete);
        QCOMPARE(f.stack.count(), 1);
        QCOMPARE(f.elements().size(), std::size_t(1));
    }

    void theContextMenuOffersWhatApplies()
    {
        Fixture f;
        f.editor->select({});
        QList<QAction *> menu = f.editor->contextMenuActions();
        QStringList ids;
        for (QAction *action : menu)
            ids << (action->isSeparator() ? QStringLiteral("|") : action->objectName());
        QCOMPARE(ids.join(QLatin1Char(' ')), QStringLiteral("boxAdd | boxRename | boxDelete boxCount"));
        const auto enabled = [&](const char *id) { return f.editor->action(QString::fromLatin1(id))->isEnabled(); };
        QVERIFY(enabled("boxAdd"));
        QVERIFY(!enabled("boxRename"));
        QVERIFY(!enabled("boxDelete"));
        f.editor->select({2});
        menu = f.editor->contextMenuActions();
        QVERIFY(enabled("boxRename"));
        QVERIFY(enabled("boxDelete"));
    }

    void rightClickSelectsAndTheMenuKeyOpensAtTheSelection()
    {
        Fixture f;
        f.editor->show();
        QVERIFY(QTest::qWaitForWindowExposed(f.editor.get()));
        DiagramView *view = f.editor->view();
        QTest::mouseClick(view->viewport(), Qt::RightButton, {}, view->mapFromScene(QPointF(110, 10)));
        QCOMPARE(f.editor->selection(), QList<quint64> {2});
        QVERIFY(f.editor->action(QStringLiteral("boxDelete"))->isEnabled());
        // The Menu key (and Shift+F10) opens the menu where the selected element is.
        const QPoint element = view->viewport()->mapToGlobal(view->mapFromScene(QPointF(120, 10)));
        for (const QKeySequence &keys : {QKeySequence(Qt::Key_Menu), QKeySequence(Qt::SHIFT | Qt::Key_F10)}) {
            QRect shownAt;
            QStringList entries;
            QTimer::singleShot(0, this, [&] {
                if (auto *menu = qobject_cast<QMenu *>(QApplication::activePopupWidget())) {
                    shownAt = menu->geometry();
                    for (QAction *action : menu->actions())
                        entries << action->objectName();
                    menu->close();
                }
            });
            view->setFocus();
            QTest::keySequence(view, keys);
            QVERIFY2(shownAt.isValid(), qPrintable(keys.toString()));
            QCOMPARE(shownAt.topLeft(), element);
            QVERIFY(entries.contains(QStringLiteral("boxDelete")));
        }
    }

    void arrowsNavigateAndEnterActivates()
    {
        Fixture f;
        f.editor->select({1});
        QTest::keyClick(f.editor->view(), Qt::Key_Right);
        QCOMPARE(f.editor->selection(), QList<quint64> {2});
        QTest::keyClick(f.editor->view(), Qt::Key_Right);
        QCOMPARE(f.editor->selection(), QList<quint64> {2}); // nothing further right
        QTest::keyClick(f.editor->view(), Qt::Key_Left);
        QCOMPARE(f.editor->selection(), QList<quint64> {1});
        QTest::keyClick(f.editor->view(), Qt::Key_Return);
        QCOMPARE(f.editor->activated, 1);
    }

    void actionsFollowTheUiLanguage()
    {
        Fixture f;
        QToolBar *bar = f.editor->findChild<QToolBar *>(QStringLiteral("diagramToolBar"));
        QVERIFY(bar);
        const auto buttonText = [&](const char *id) {
            auto *button = qobject_cast<QToolButton *>(bar->widgetForAction(f.editor->action(QString::fromLatin1(id))));
            return button ? button->text() : QString();
        };
        QCOMPARE(buttonText("boxAdd"), QStringLiteral("Add Box"));
        tests::BracketTranslator translator;
        tests::switchLanguage(&translator, nullptr);
        QCOMPARE(f.editor->action(QStringLiteral("boxAdd"))->text(), QStringLiteral("[Add Box]"));
        QCOMPARE(f.editor->action(QStringLiteral("zoomIn"))->text(), QStringLiteral("[Zoom In]"));
        QCOMPARE(buttonText("boxAdd"), QStringLiteral("[Add Box]"));
        tests::switchLanguage(nullptr, &translator);
        QCOMPARE(f.editor->action(QStringLiteral("boxAdd"))->text(), QStringLiteral("Add Box"));
        // Switching again and again does not pile up.
        tests::switchLanguage(&translator, nullptr);
        tests::switchLanguage(nullptr, &translator);
        tests::switchLanguage(&translator, nullptr);
        QCOMPARE(f.editor->action(QStringLiteral("boxDelete"))->text(), QStringLiteral("[Delete]"));
        tests::switchLanguage(nullptr, &translator);
    }

    void dragsAndWiresAreOneUndoStepEach()
    {
        Fixture f;
        static_cast<tests::BoxPolicy &>(f.editor->policy()).mouseEditing = true;
        f.editor->setGridSize(20);
        f.editor->show();
        QVERIFY(QTest::qWaitForWindowExposed(f.editor.get()));
        DiagramView *view = f.editor->view();
        f.editor->select({2});
        QTest::mousePress(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(QPointF(110, 10)));
        QTest::mouseMove(view->viewport(), view->mapFromScene(QPointF(120, 40)));
        QTest::mouseMove(view->viewport(), view->mapFromScene(QPointF(131, 52)));
        QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(QPointF(131, 52)));
        QCOMPARE(f.stack.count(), 1);
        QCOMPARE(model::header(f.elements()[1]).position, (model::Position {120, 40}));
        // A second drag of the same box is a step of its own.
        QTest::mousePress(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(QPointF(130, 50)));
        QTest::mouseMove(view->viewport(), view->mapFromScene(QPointF(150, 50)));
        QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(QPointF(150, 50)));
        QCOMPARE(f.stack.count(), 2);
        QCOMPARE(model::header(f.elements()[1]).position, (model::Position {140, 40}));
        // A wire from A's output to B's input.
        QTest::mousePress(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(QPointF(40, 10)));
        QTest::mouseMove(view->viewport(), view->mapFromScene(QPointF(90, 30)));
        QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(QPointF(141, 50)));
        QCOMPARE(f.stack.count(), 3);
        const auto &in = std::get<model::OutVariable>(f.elements()[1]).connectionPointIn->connections;
        QCOMPARE(in.size(), std::size_t(1));
        QCOMPARE(in.front().refLocalId, quint64(1));
        f.stack.undo();
        f.stack.undo();
        f.stack.undo();
        QCOMPARE(model::header(f.elements()[1]).position, (model::Position {100, 0}));
        // Online nothing moves.
        f.goOnline();
        QTest::mousePress(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(QPointF(110, 10)));
        QTest::mouseMove(view->viewport(), view->mapFromScene(QPointF(160, 60)));
        QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(QPointF(160, 60)));
        QCOMPARE(model::header(f.elements()[1]).position, (model::Position {100, 0}));
        QCOMPARE(f.stack.index(), 0);
    }

    void diagnosticsMarkTheirElements()
    {
        Fixture f;
        f.editor->setDiagnostics({{2, ElementDiagnostic::Severity::Error, QStringLiteral("B is not declared.")},
            {2, ElementDiagnostic::Severity::Warning, QStringLiteral("B is never read.")}});
        QCOMPARE(f.editor->scene()->itemFor(2)->diagnosticMessage(), QStringLiteral("B is not declared.\nB is never read."));
        QCOMPARE(f.editor->scene()->itemFor(2)->toolTip(), QStringLiteral("B is not declared.\nB is never read."));
        QCOMPARE(f.editor->scene()->itemFor(2)->childItems().size(), 1); // the frame
        QVERIFY(f.editor->scene()->itemFor(1)->diagnosticMessage().isEmpty());
        // They stay on the element when the scene is built again, and go when replaced.
        f.editor->scene()->rebuild();
        QCOMPARE(f.editor->scene()->itemFor(2)->diagnosticMessage(), QStringLiteral("B is not declared.\nB is never read."));
        f.editor->setDiagnostics({});
        QVERIFY(f.editor->scene()->itemFor(2)->diagnosticMessage().isEmpty());
        QVERIFY(f.editor->scene()->itemFor(2)->childItems().isEmpty());
    }

    void theOverlayGoesThroughTheMapper()
    {
        Fixture f;
        QCOMPARE(f.editor->onlineNames(), QStringList {QStringLiteral("Main.A")});
        QVERIFY(!f.editor->wantsChartState());
        f.goOnline();
        QVERIFY(f.editor->isOnline());
        QVERIFY(f.editor->scene()->itemFor(1)->isActive());
        // Items made again are styled again.
        f.editor->scene()->rebuild();
        QVERIFY(f.editor->scene()->itemFor(1)->isActive());
        f.editor->setOnlineSnapshot(nullptr);
        QVERIFY(!f.editor->scene()->itemFor(1)->isActive());
        QVERIFY(f.model.body(f.ref)->elements()->size() == 2); // the model never changed
    }

    void textIsEditedInPlace()
    {
        Fixture f;
        TwoNames names;
        f.editor->setCompletionProvider(&names);
        f.editor->show();
        QVERIFY(QTest::qWaitForWindowExposed(f.editor.get()));
        QStringList committed;
        const auto open = [&] {
            return QPointer<InPlaceEditor>(f.editor->editTextInPlace(QRectF(0, 30, 40, 20), QStringLiteral("???"),
                InPlaceEditor::Completion::Names, [&](const QString &text) { committed << text; }));
        };
        const auto gone = [](const QPointer<InPlaceEditor> &line) {
            QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
            return line.isNull();
        };
        // A new name is selected for typing; completion offers the declared names.
        QPointer<InPlaceEditor> line = open();
        QVERIFY(line);
        QCOMPARE(line->selectedText(), QStringLiteral("???"));
        QTRY_VERIFY(line->hasFocus());
        line->setText(QStringLiteral("NOT Sta"));
        QVERIFY(line->completions().contains(QStringLiteral("Start")));
        QVERIFY(!line->completions().contains(QStringLiteral("Stop")));
        line->setText(QStringLiteral("T"));
        QVERIFY(line->completions().contains(QStringLiteral("TON"))); // the standard library too
        line->setText(QStringLiteral(" Start "));
        QTest::keyClick(line, Qt::Key_Return);
        QCOMPARE(committed, QStringList {QStringLiteral("Start")});
        QVERIFY(gone(line));
        // Escape cancels.
        line = open();
        line->setText(QStringLiteral("Stop"));
        QTest::keyClick(line, Qt::Key_Escape);
        QCOMPARE(committed.size(), 1);
        QVERIFY(gone(line));
        // Leaving the line commits it once.
        line = open();
        QTRY_VERIFY(line->hasFocus());
        line->setText(QStringLiteral("Stop"));
        f.editor->view()->setFocus();
        QCOMPARE(committed, (QStringList {QStringLiteral("Start"), QStringLiteral("Stop")}));
        QVERIFY(gone(line));
        // Online nothing opens, and going online closes an open line without a commit.
        line = open();
        f.goOnline();
        QVERIFY(gone(line));
        QCOMPARE(committed.size(), 2);
        QVERIFY(!open());
        QVERIFY(f.editor->lastMessage().contains(QStringLiteral("online")));
    }

    void zoomStepsReportAPercentage()
    {
        Fixture f;
        QSignalSpy zoomed(f.editor.get(), &DiagramEditor::zoomChanged);
        QCOMPARE(f.editor->zoomPercent(), 100);
        QVERIFY(f.editor->trigger(QStringLiteral("zoomIn")));
        QCOMPARE(zoomed.count(), 1);
        QCOMPARE(zoomed.front().at(0).toInt(), f.editor->zoomPercent());
        QVERIFY(f.editor->zoomPercent() > 100);
    }
};

QTEST_MAIN(TestDiagramEditor)
#include "tst_diagrameditor.moc"
