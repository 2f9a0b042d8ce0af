// The headline of issue 7 in the main window: the mixing-tank chart of seed 001 drawn with SFC
// editor commands only, saved and read back to the same model, then run online cycle by cycle
// with the inputs written through the watch pane, checking after each cycle which steps the
// open editor draws active (blue) and what the outputs are. Also: editing is refused while
// online, the Insert menu offers the chart commands, and pictures of the chart offline and
// online (IEC_SHOT_DIR=DIR saves DIR/sfc_offline.png and DIR/sfc_online.png).
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/online/onlinecontroller.h"
#include "app/online/watchpane.h"
#include "app/projecttreeactions.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "app/undoactions.h"
#include "app/undostacks.h"
#include "editors/common/diagramitem.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/datatypes/datatypeeditor.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/text/codeeditor.h"
#include "editors/sfc/sfceditor.h"
#include "editors/sfc/sfcitems.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/runtime/snapshot.h"
#include "model/body.h"
#include "model/projectmodel.h"
#include "tests/editors/sfcmixingtank.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace iec;
using namespace iec::app;
using editors::sfc::SfcEditor;
using model::BodyRef;
using model::Element;

namespace {

const char *const kInputs[] = {"SB1", "SB2", "L1", "L2", "L3"};
const char *const kOutputs[] = {"Y1", "Y2", "Y3", "M"};

model::VarList boolList(model::VarListKind kind, const char *const *names, size_t count)
{
    model::VarList list;
    list.kind = kind;
    for (size_t i = 0; i < count; ++i) {
        model::Variable variable;
        variable.name = QString::fromLatin1(names[i]);
        variable.type.kind = model::ElementaryType {QStringLiteral("BOOL")};
        list.variables.push_back(variable);
    }
    return list;
}

// The program Tank with its variables declared and an empty SFC body.
model::Project projectWithEmptyChart()
{
    model::Project project;
    project.contentHeader.name = QStringLiteral("MixingTank");
    model::Pou pou;
    pou.name = QStringLiteral("Tank");
    pou.kind = model::PouKind::Program;
    model::Interface interface;
    interface.varLists.push_back(boolList(model::VarListKind::Input, kInputs, std::size(kInputs)));
    interface.varLists.push_back(boolList(model::VarListKind::Local, kOutputs, std::size(kOutputs)));
    pou.pouInterface = interface;
    pou.bodies.push_back(model::Body::withLanguage(model::BodyLanguage::SFC));
    project.types.pous.push_back(pou);
    model::DataTypeDecl percent; // for the data type editor while online
    percent.name = QStringLiteral("Percent");
    percent.baseType.kind = model::ElementaryType {QStringLiteral("INT")};
    project.types.dataTypes.push_back(percent);
    return project;
}

// The names of the steps the editor draws active (blue), in chart order.
QStringList activeSteps(const SfcEditor &editor)
{
    QStringList names;
    for (editors::DiagramItem *item : editor.scene()->diagramItems()) {
        const auto *sfcItem = static_cast<editors::sfc::SfcItem *>(item);
        if (const auto *step = std::get_if<model::Step>(&sfcItem->element()); step && item->isActive())
            names.push_back(step->name);
    }
    return names;
}

// The elapsed time the editor shows on the step `name` ("" when none).
QString stepTimeText(const SfcEditor &editor, const QString &name)
{
    for (editors::DiagramItem *item : editor.scene()->diagramItems()) {
        const auto *sfcItem = static_cast<editors::sfc::SfcItem *>(item);
        if (const auto *step = std::get_if<model::Step>(&sfcItem->element()); step && step->name == name)
            return item->onlineText();
    }
    return {};
}

void saveShot(QWidget &window, const QString &fileName)
{
    QCoreApplication::processEvents();
    const QImage image = window.grab().toImage();
    QVERIFY(!image.isNull());
    const QByteArray dir = qgetenv("IEC_SHOT_DIR");
    if (!dir.isEmpty())
        QVERIFY(image.save(QDir(QString::fromLocal8Bit(dir)).filePath(fileName)));
}

} // namespace

class TestSfcOnline : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void mixingTankRunsOnlineInTheWindow();
    void editingIsRefusedWhileOnline();
    void everyEditingKeySaysWhyOnline_data();
    void everyEditingKeySaysWhyOnline();
    void insertMenuFollowsTheCurrentEditor();
    void chartInAnActionRunsOnline();

private:
    // A window with the empty chart open in its SFC editor, the controller synchronous.
    std::unique_ptr<MainWindow> windowWithEmptyChart();
    static SfcEditor *chartEditor(MainWindow &window);
    // Draws the mixing tank: Init -SB1-> Fill_A (Y1) -L2-> Fill_B (Y2) -L1-> Mix (M)
    // -Mix.T >= T#3s-> Drain (Y3) -> [NOT L3 AND NOT SB2 -> Fill_A | NOT L3 AND SB2 -> Init].
    static void buildMixingTank(SfcEditor &editor);

    QTemporaryDir m_configHome;
    QTemporaryDir m_files;
};

void TestSfcOnline::initTestCase()
{
    qputenv("XDG_CONFIG_HOME", m_configHome.path().toLocal8Bit());
    QCoreApplication::setOrganizationName(QStringLiteral("IEC Studio Tests"));
}

std::unique_ptr<MainWindow> TestSfcOnline::windowWithEmptyChart()
{
    auto window = std::make_unique<MainWindow>();
    window->online().setThreaded(false);
    window->projectModel().reset(projectWithEmptyChart());
    const model::Pou *tank = window->projectModel().project().findPou(QStringLiteral("Tank"));
    window->documents().openBody({tank->id, BodyRef::Part::Pou, {}});
    return window;
}

SfcEditor *TestSfcOnline::chartEditor(MainWindow &window)
{
    const model::Pou *tank = window.projectModel().project().findPou(QStringLiteral("Tank"));
    QWidget *document = tank ? window.documents().documentFor({tank->id, BodyRef::Part::Pou, {}}) : nullptr;
    return document ? document->findChild<SfcEditor *>() : nullptr;
}

void TestSfcOnline::buildMixingTank(SfcEditor &e)
{
    tests::buildMixingTank(e, "Mix.T >= T#3s", [&e](const char *what, const std::function<bool()> &command) {
        QVERIFY2(command(), qPrintable(QStringLiteral("%1: %2").arg(QLatin1String(what), e.lastMessage())));
    });
}

void TestSfcOnline::mixingTankRunsOnlineInTheWindow()
{
    auto window = windowWithEmptyChart();
    window->resize(1280, 900);
    window->show();
    SfcEditor *editor = chartEditor(*window);
    QVERIFY(editor);
    buildMixingTank(*editor);
    if (QTest::currentTestFailed())
        return;

    // Saved and read back: the same program, the editor open on it again.
    const model::Pou built = *window->projectModel().project().findPou(QStringLiteral("Tank"));
    const QString path = m_files.filePath(QStringLiteral("mixing_tank.xml"));
    QString error;
    QVERIFY2(window->saveProject(path, &error), qPrintable(error));
    QVERIFY2(window->openProject(path, &error), qPrintable(error));
    const model::Pou *reloaded = window->projectModel().project().findPou(QStringLiteral("Tank"));
    QVERIFY(reloaded);
    QCOMPARE(reloaded->bodies, built.bodies);
    QCOMPARE(reloaded->pouInterface, built.pouInterface);
    QCOMPARE(reloaded->actions, built.actions);
    window->documents().openBody({reloaded->id, BodyRef::Part::Pou, {}});
    editor = chartEditor(*window);
    QVERIFY(editor);
    editor->fitToWindow();
    QVERIFY(activeSteps(*editor).isEmpty());
    saveShot(*window, QStringLiteral("sfc_offline.png"));

    // Online, one-second cycles so that Mix.T >= T#3s takes a few cycles.
    WatchPane &watch = window->watchPane();
    for (const char *name : kInputs)
        QVERIFY(watch.addVariable(QStringLiteral("Tank.%1").arg(QLatin1String(name))));
    for (const char *name : kOutputs)
        QVERIFY(watch.addVariable(QStringLiteral("Tank.%1").arg(QLatin1String(name))));
    OnlineController &online = window->online();
    online.setCycleTime(1'000'000'000);
    QVERIFY(online.login());
    QVERIFY(editor->isOnline());

    // Each row: the inputs written through the watch pane before the cycle, then after the
    // cycle the steps drawn blue and Y1 Y2 M Y3.
    struct Cycle {
        QList<std::pair<const char *, const char *>> writes;
        QStringList active;
        const char *outputs; // Y1 Y2 M Y3 as 0/1
    };
    // A transition that holds fires at the end of the cycle; its target is active from the
    // next cycle on, and runs its action in that cycle (docs/sfc.md, "One cycle").
    const QList<Cycle> cycles = {
        {{}, {QStringLiteral("Init")}, "0000"},
        {{}, {QStringLiteral("Init")}, "0000"},
        {{{"SB1", "TRUE"}}, {QStringLiteral("Init")}, "0000"}, // SB1 holds: fires
        {{{"SB1", "FALSE"}}, {QStringLiteral("Fill_A")}, "1000"},
        {{{"L2", "TRUE"}}, {QStringLiteral("Fill_A")}, "1000"},
        {{{"L2", "FALSE"}}, {QStringLiteral("Fill_B")}, "0100"},
        {{{"L1", "TRUE"}, {"L3", "TRUE"}}, {QStringLiteral("Fill_B")}, "0100"},
        {{{"L1", "FALSE"}}, {QStringLiteral("Mix")}, "0010"}, // Mix.T = 0 s
        {{}, {QStringLiteral("Mix")}, "0010"}, // 1 s
        {{}, {QStringLiteral("Mix")}, "0010"}, // 2 s
        {{}, {QStringLiteral("Mix")}, "0010"}, // 3 s: Mix.T >= T#3s fires
        {{}, {QStringLiteral("Drain")}, "0001"},
        {{{"SB2", "TRUE"}}, {QStringLiteral("Drain")}, "0001"}, // L3 still TRUE: stays
        {{{"L3", "FALSE"}}, {QStringLiteral("Drain")}, "0001"}, // NOT L3 AND SB2: fires
        {{}, {QStringLiteral("Init")}, "0000"},
        {{{"SB1", "TRUE"}}, {QStringLiteral("Init")}, "0000"},
        {{}, {QStringLiteral("Fill_A")}, "1000"},
    };
    const auto row = [&watch](const char *name) { return watch.model().rowOf(QStringLiteral("Tank.%1").arg(QLatin1String(name))); };
    int number = 0;
    QStringList mismatches;
    for (const Cycle &cycle : cycles) {
        ++number;
        for (const auto &[name, literal] : cycle.writes)
            watch.model().setPrepared(row(name), QLatin1String(literal));
        if (!cycle.writes.isEmpty())
            watch.writePrepared();
        online.singleCycle();
        QCOMPARE(online.latestSnapshot()->cycle, number);
        QString outputs;
        for (const char *name : kOutputs)
            outputs += watch.model().value(row(name)) == QStringLiteral("TRUE") ? QLatin1Char('1') : QLatin1Char('0');
        // Y1 Y2 Y3 M in kOutputs order; the table says Y1 Y2 M Y3.
        const QString expected = QString::fromLatin1(cycle.outputs);
        const QString table = QString(outputs[0]) + outputs[1] + outputs[3] + outputs[2];
        if (activeSteps(*editor) != cycle.active || table != expected)
            mismatches << QStringLiteral("cycle %1: active %2 (expected %3), Y1 Y2 M Y3 %4 (expected %5)")
                              .arg(number)
                              .arg(activeSteps(*editor).join(QLatin1Char(',')), cycle.active.join(QLatin1Char(',')),
                                   table, expected);
        if (number == 9)
            QCOMPARE(stepTimeText(*editor, QStringLiteral("Mix")), QStringLiteral("T#1s"));
        if (number == 11) { // Mix active for 3 s, its transition TRUE (marked)
            QCOMPARE(stepTimeText(*editor, QStringLiteral("Mix")), QStringLiteral("T#3s"));
            saveShot(*window, QStringLiteral("sfc_online.png"));
        }
    }
    QVERIFY2(mismatches.isEmpty(), qPrintable(mismatches.join(QLatin1Char('\n'))));
    // The active step shows its elapsed time; nothing went into the model or an undo stack.
    QVERIFY(!stepTimeText(*editor, QStringLiteral("Fill_A")).isEmpty());
    QVERIFY(stepTimeText(*editor, QStringLiteral("Mix")).isEmpty());
    QVERIFY(!window->hasUnsavedChanges());

    online.logout();
    QVERIFY(!editor->isOnline());
    QVERIFY(activeSteps(*editor).isEmpty());
}

void TestSfcOnline::editingIsRefusedWhileOnline()
{
    auto window = windowWithEmptyChart();
    window->show();
    SfcEditor *editor = chartEditor(*window);
    QVERIFY(editor->trigger(QStringLiteral("sfcNewChart")));
    const model::Pou *tank = window->projectModel().project().findPou(QStringLiteral("Tank"));
    const std::vector<model::Body> before = tank->bodies;
    QUndoStack &stack = window->undoStacks().pouStack(tank->id);
    QVERIFY(stack.canUndo());
    const BodyRef ref {tank->id, BodyRef::Part::Pou, {}};
    auto *tree = window->findChild<ProjectTreeView *>(QStringLiteral("projectTree"));
    tree->selectKey(ProjectTreeModel::pouKey(tank->id));
    auto *treeActions = window->findChild<ProjectTreeActions *>();
    const char *const treeActionNames[] = {"addPouAction", "renameAction", "deleteAction", "duplicateAction"};
    for (const char *name : treeActionNames)
        QVERIFY2(window->findChild<QAction *>(QString::fromLatin1(name))->isEnabled(), name);
    editors::DeclarationEditor *declarations = window->documents().declarationEditorFor(ref);
    QVERIFY(declarations);
    const auto tableTriggers = declarations->table()->editTriggers();
    QVERIFY(tableTriggers != QAbstractItemView::NoEditTriggers);
    QVERIFY(!declarations->textEditor()->isReadOnly());
    OnlineController &online = window->online();
    QVERIFY(online.login());

    // The chart editor refuses its commands and says why.
    editor->select({editor->stepId(QStringLiteral("Init"))});
    QVERIFY(!editor->trigger(QStringLiteral("sfcStepAfter")));
    QVERIFY2(editor->lastMessage().contains(QStringLiteral("Logout")), qPrintable(editor->lastMessage()));
    QVERIFY(!editor->insertActions().isEmpty());
    for (QAction *action : editor->insertActions())
        QVERIFY2(!action->isEnabled(), qPrintable(action->objectName()));
    // Undo and redo are off, and the window says how to edit again.
    QAction *undo = window->findChild<QAction *>(QStringLiteral("undoAction"));
    QVERIFY(undo);
    QVERIFY(!undo->isEnabled());
    undo->trigger();
    QCOMPARE(window->projectModel().project().findPou(QStringLiteral("Tank"))->bodies, before);
    QVERIFY2(window->statusBar()->currentMessage().contains(QStringLiteral("Log out to edit")),
             qPrintable(window->statusBar()->currentMessage()));
    // The project tree's add/rename/delete/duplicate are off, its in-place rename is refused.
    for (const char *name : treeActionNames)
        QVERIFY2(!window->findChild<QAction *>(QString::fromLatin1(name))->isEnabled(), name);
    window->statusBar()->clearMessage();
    treeActions->renameInPlace(ref, QStringLiteral("Other"));
    QVERIFY(window->projectModel().project().findPou(QStringLiteral("Tank")));
    QVERIFY(window->statusBar()->currentMessage().contains(QStringLiteral("Log out to edit")));
    // The declarations are only shown; Ctrl+Z in their table changes nothing either.
    QCOMPARE(declarations->table()->editTriggers(), QAbstractItemView::NoEditTriggers);
    QVERIFY(declarations->textEditor()->isReadOnly());
    window->statusBar()->clearMessage();
    declarations->showTable();
    declarations->table()->setFocus();
    QTest::keyClick(declarations->table(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(window->projectModel().project().findPou(QStringLiteral("Tank"))->bodies, before);
    QVERIFY(window->statusBar()->currentMessage().contains(QStringLiteral("Log out to edit")));

    // A data type opened while online is only shown too.
    editors::DataTypeEditor *types = qobject_cast<editors::DataTypeEditor *>(window->documents().openDataType(QStringLiteral("Percent")));
    QVERIFY(types);
    QVERIFY(types->nameEdit()->isReadOnly());
    QVERIFY(!types->kindBox()->isEnabled());

    online.logout();
    QVERIFY(!types->nameEdit()->isReadOnly());
    QVERIFY(types->kindBox()->isEnabled());
    for (const char *name : treeActionNames)
        QVERIFY2(window->findChild<QAction *>(QString::fromLatin1(name))->isEnabled(), name);
    QCOMPARE(declarations->table()->editTriggers(), tableTriggers);
    QVERIFY(!declarations->textEditor()->isReadOnly());
    // Offline the insert commands that apply to the selected initial step are back: all but a new
    // chart (there is one) and the alternative branches (they need a transition).
    QStringList enabled;
    for (QAction *action : editor->insertActions())
        if (action->isEnabled())
            enabled << action->objectName();
    QCOMPARE(enabled, (QStringList {QStringLiteral("sfcStepAfter"), QStringLiteral("sfcStepBefore"), QStringLiteral("sfcParRight"),
                          QStringLiteral("sfcParLeft"), QStringLiteral("sfcJump"), QStringLiteral("sfcTransitionJump"),
                          QStringLiteral("sfcMacro")}));
    QVERIFY(!window->findChild<UndoActions *>()->isLocked());
    QVERIFY(editor->trigger(QStringLiteral("sfcStepAfter")));
}

void TestSfcOnline::everyEditingKeySaysWhyOnline_data()
{
    QTest::addColumn<QKeySequence>("keys");
    QTest::newRow("Delete") << QKeySequence(Qt::Key_Delete);
    QTest::newRow("Ctrl+T") << QKeySequence(Qt::CTRL | Qt::Key_T);
    QTest::newRow("Ctrl+Shift+T") << QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_T);
    QTest::newRow("Ctrl+L") << QKeySequence(Qt::CTRL | Qt::Key_L);
    QTest::newRow("Ctrl+A") << QKeySequence(Qt::CTRL | Qt::Key_A);
    QTest::newRow("Ctrl+X") << QKeySequence(Qt::CTRL | Qt::Key_X);
    QTest::newRow("Ctrl+V") << QKeySequence(Qt::CTRL | Qt::Key_V);
    QTest::newRow("Enter") << QKeySequence(Qt::Key_Return);
}

void TestSfcOnline::everyEditingKeySaysWhyOnline()
{
    // As a user does it: the step clicked in the window's chart, then the key, wherever Qt
    // delivers it (shortcut map, focus widget).
    QFETCH(QKeySequence, keys);
    auto window = windowWithEmptyChart();
    window->show();
    QApplication::setActiveWindow(window.get());
    QVERIFY(QTest::qWaitForWindowActive(window.get()));
    SfcEditor *editor = chartEditor(*window);
    QVERIFY(editor->trigger(QStringLiteral("sfcNewChart")));
    QVERIFY(editor->trigger(QStringLiteral("sfcStepAfter")));
    const model::Pou *tank = window->projectModel().project().findPou(QStringLiteral("Tank"));
    const std::vector<model::Body> before = tank->bodies;
    QVERIFY(window->online().login());
    const quint64 step = editor->stepId(QStringLiteral("Step1"));
    editors::DiagramView *view = editor->view();
    const QPoint at = view->mapFromScene(editor->scene()->itemFor(step)->frame().center());
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, at);
    QCOMPARE(editor->selection(), QList<quint64> {step});
    QVERIFY(QApplication::focusWidget());
    editor->showMessage(QString());
    QTest::keySequence(QApplication::focusWidget(), keys);
    const QString refusal = QStringLiteral("The diagram cannot be changed while online. Log out first (Online → Logout).");
    QCOMPARE(editor->lastMessage(), refusal);
    // The window's Edit menu says the same (its Cut, Paste and Delete are the editor's).
    for (const char *name : {"cutAction", "pasteAction", "deleteEditAction"}) {
        editor->showMessage(QString());
        window->findChild<QAction *>(QString::fromLatin1(name))->trigger();
        QCOMPARE(editor->lastMessage(), refusal);
    }
    QCOMPARE(window->projectModel().project().findPou(QStringLiteral("Tank"))->bodies, before);
    window->online().logout();
}

void TestSfcOnline::insertMenuFollowsTheCurrentEditor()
{
    auto window = windowWithEmptyChart();
    window->show();
    SfcEditor *editor = chartEditor(*window);
    QVERIFY(editor);
    auto *insertMenu = window->menuBar()->findChild<QMenu *>(QStringLiteral("insertMenu"));
    QVERIFY(insertMenu);
    QCoreApplication::processEvents();
    QVERIFY(!editor->insertActions().isEmpty());
    QStringList chartCommands;
    for (QAction *action : editor->insertActions()) {
        QVERIFY2(insertMenu->actions().contains(action), qPrintable(action->objectName()));
        chartCommands << action->objectName();
    }
    // With no chart editor in front, the chart commands leave the menu.
    window->documents().closeAll();
    QCoreApplication::processEvents();
    for (QAction *action : insertMenu->actions())
        QVERIFY2(!chartCommands.contains(action->objectName()), qPrintable(action->objectName()));
    QVERIFY(!insertMenu->actions().isEmpty());
}

// A chart that is an action's body (here of an ST program, read from .st text) is animated like
// the POU's own: its active step in blue with its time, cycle by cycle.
void TestSfcOnline::chartInAnActionRunsOnline()
{
    MainWindow window;
    window.online().setThreaded(false);
    const interp::frontend::TextReadResult text = interp::frontend::readIecText(
        QStringLiteral("PROGRAM Main\nVAR go : BOOL := TRUE; n : INT; END_VAR\nSeq();\n"
                       "ACTION Seq:\nINITIAL_STEP Idle: END_STEP\nTRANSITION FROM Idle TO Fill := go; END_TRANSITION\n"
                       "STEP Fill: Count(N); END_STEP\nTRANSITION FROM Fill TO Idle := n >= 2; END_TRANSITION\nEND_ACTION\n"
                       "ACTION Count:\nn := n + 1;\nEND_ACTION\nEND_PROGRAM\n"),
        QStringLiteral("Charts"));
    QVERIFY(!text.diagnostics.hasErrors());
    window.projectModel().reset(text.project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QVERIFY(main);
    QWidget *document = window.documents().openBody({main->id, BodyRef::Part::Action, QStringLiteral("Seq")});
    auto *editor = qobject_cast<SfcEditor *>(document);
    if (!editor && document)
        editor = document->findChild<SfcEditor *>();
    QVERIFY(editor);
    QVERIFY(window.online().login());
    QStringList cycles;
    for (int cycle = 0; cycle < 5; ++cycle) {
        window.online().singleCycle();
        cycles << activeSteps(*editor).join(QLatin1Char(',')) + QLatin1Char(' ') + stepTimeText(*editor, QStringLiteral("Fill"));
    }
    // Idle's transition fires in cycle 1; Fill counts n to 2 over two cycles, then Idle again.
    QCOMPARE(cycles.join(QLatin1Char('|')), QStringLiteral("Idle |Fill T#0s|Fill T#10ms|Idle |Fill T#0s"));
    window.online().logout();
    QVERIFY(activeSteps(*editor).isEmpty());
}

QTEST_MAIN(TestSfcOnline)
#include "tst_sfconline.moc"
