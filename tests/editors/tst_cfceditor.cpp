// The CFC editor driven as a user drives it: elements placed where the mouse pressed, names typed
// in place, wires dragged from pin to pin, an element dragged so close that its wire turns red
// and back, the execution order set by data flow and changed; the chart runs as the order says.
// The saved file validates against the TC6 XSD after every command, and undo/redo restore the
// exact model.
#include "editors/cfc/cfceditor.h"
#include "editors/cfc/cfcgeometry.h"
#include "editors/cfc/cfcscene.h"
#include "editors/cfc/cfcstorage.h"
#include "editors/common/blockitems.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/common/editorlanguage.h"
#include "editors/common/inplaceeditor.h"
#include "editors/text/completion.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"
#include "tests/model/roundtrip.h"

#include <QApplication>
#include <QDropEvent>
#include <QMimeData>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>

using namespace iec;
using namespace iec::editors::cfc;

namespace {

const char *const kDeclarations = "VAR Count : INT; Done : BOOL; T1 : TON; END_VAR";

model::Project cfcProject()
{
    const QString text = QStringLiteral("PROGRAM Main\n") + QLatin1String(kDeclarations) + QStringLiteral("\nEND_PROGRAM\n");
    auto read = interp::frontend::readIecText(text, QStringLiteral("cfc"));
    for (model::Pou &pou : read.project.types.pous) {
        if (pou.name != QLatin1String("Main"))
            continue;
        model::Body body = model::Body::withLanguage(model::BodyLanguage::FBD);
        body.addData.push_back({QString::fromLatin1(editors::kIecStudioCfcAddDataName), QStringLiteral("implementation"), QStringLiteral("<cfc/>")});
        pou.bodies = {body};
    }
    read.project.fileHeader.creationDateTime = QStringLiteral("2026-11-26T10:00:00");
    return read.project;
}

// Count and Done after each of `scans` scans of 10 ms, as "Count/Done" rows.
QString trace(const model::Project &project, int scans)
{
    interp::Diagnostics diagnostics;
    const auto module = interp::frontend::compileProject(project, diagnostics);
    if (!module) {
        QStringList messages;
        for (const interp::Diagnostic &d : diagnostics.all())
            messages << d.toString();
        return QStringLiteral("does not compile: ") + messages.join(QLatin1Char('\n'));
    }
    interp::Runtime runtime(module);
    QStringList rows;
    for (int scan = 1; scan <= scans; ++scan) {
        if (!runtime.runCycle())
            return QStringLiteral("stopped");
        rows << runtime.read(QStringLiteral("Main.Count")).value_or(QStringLiteral("?")) + QLatin1Char('/')
                + runtime.read(QStringLiteral("Main.Done")).value_or(QStringLiteral("?"));
    }
    return rows.join(QLatin1Char(' '));
}

class DeclaredNames : public editors::CompletionProvider
{
public:
    QList<editors::CompletionItem> variables() const override
    {
        QList<editors::CompletionItem> items;
        for (const char *name : {"Count", "Done", "T1"})
            items.push_back({QLatin1String(name), editors::CompletionItem::Kind::Variable, {}, {}});
        return items;
    }
    QList<editors::CompletionItem> members(const QString &) const override { return {}; }
    QList<editors::CompletionItem> pous() const override { return {}; }
};

} // namespace

class TestCfcEditor : public QObject
{
    Q_OBJECT

private:
    model::ProjectModel m_model;
    QUndoStack m_stack;
    std::unique_ptr<CfcEditor> m_editor;
    DeclaredNames m_names;
    std::vector<model::Project> m_after;
    QStringList m_problems;

    model::PouId mainId() const { return m_model.project().findPou(QStringLiteral("Main"))->id; }
    QWidget *viewport() const { return m_editor->view()->viewport(); }
    QPoint at(QPointF scenePos) const { return m_editor->view()->mapFromScene(scenePos); }

    void open(model::Project project)
    {
        m_model.reset(std::move(project));
        m_stack.clear();
        m_editor = std::make_unique<CfcEditor>(m_model, model::BodyRef {mainId()}, &m_stack);
        m_editor->setCompletionProvider(&m_names);
        m_editor->resize(1200, 800);
        m_editor->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_editor.get()));
        m_editor->setGridSize(10);
        m_editor->view()->centerOn(QPointF(350, 250));
        m_after.clear();
        m_problems.clear();
    }

    void checkpoint(const QString &what)
    {
        const QString errors = iec::test::schemaErrors(model::plcopen::writeProject(m_model.project()));
        if (!errors.isEmpty())
            m_problems << what + QStringLiteral(": ") + errors;
        m_after.push_back(m_model.project());
    }

    // A click on the empty sheet: where the next element goes.
    void clickSheet(QPointF scenePos)
    {
        QTest::mouseClick(viewport(), Qt::LeftButton, {}, at(scenePos));
    }

    bool trigger(const char *id)
    {
        const bool ok = m_editor->trigger(QString::fromLatin1(id));
        if (!ok)
            m_problems << QStringLiteral("%1 refused: %2").arg(QLatin1String(id), m_editor->lastMessage());
        checkpoint(QLatin1String(id));
        return ok;
    }

    void type(const QString &text)
    {
        editors::InPlaceEditor *field = m_editor->inPlaceEditor();
        if (!field) {
            m_problems << QStringLiteral("no field to type '%1' into").arg(text);
            return;
        }
        field->selectAll();
        QTest::keyClicks(field, text);
        QTest::keyClick(field, Qt::Key_Return);
        checkpoint(QStringLiteral("type ") + text);
    }

    // Places an element: a click where it goes, the command, its name typed.
    void place(QPointF where, const char *action, const QString &name)
    {
        // A little left of and below the corner (clear of a neighbour's frame); the element
        // snaps to the corner.
        clickSheet(where + QPointF(-5, 2));
        trigger(action);
        if (!name.isEmpty())
            type(name);
    }

    const model::Element *element(quint64 id) const
    {
        for (const model::Element &e : m_editor->elements())
            if (model::header(e).localId == id)
                return &e;
        return nullptr;
    }

    quint64 named(const QString &name) const
    {
        const quint64 id = m_editor->elementNamed(name);
        return id;
    }

    QPointF outputPin(const QString &name, const std::optional<QString> &pin = std::nullopt) const
    {
        const model::Element *e = element(named(name));
        return e ? cfcOutputPin(*e, pin).value_or(QPointF()) : QPointF();
    }

    QPointF inputPin(const QString &name, int pin) const
    {
        const model::Element *e = element(named(name));
        return e ? cfcInputPin(*e, pin).value_or(QPointF()) : QPointF();
    }

    // A wire dragged from one pin to another with the left button.
    void dragWire(QPointF from, QPointF to, const QString &what)
    {
        QTest::mousePress(viewport(), Qt::LeftButton, {}, at(from));
        QTest::mouseMove(viewport(), at((from + to) / 2));
        QTest::mouseMove(viewport(), at(to));
        QTest::mouseRelease(viewport(), Qt::LeftButton, {}, at(to));
        checkpoint(QStringLiteral("wire ") + what);
    }

    // An element dragged by its middle to put its top left at `to`.
    void dragElement(const QString &name, QPointF to)
    {
        const model::Element *e = element(named(name));
        if (!e) {
            m_problems << QStringLiteral("no element '%1' to drag").arg(name);
            return;
        }
        const QRectF rect = cfcRect(*e);
        const QPointF grab = rect.center();
        const QPointF drop = grab + (to - rect.topLeft());
        QTest::mousePress(viewport(), Qt::LeftButton, {}, at(grab));
        QTest::mouseMove(viewport(), at((grab + drop) / 2));
        QTest::mouseMove(viewport(), at(drop));
        QTest::mouseRelease(viewport(), Qt::LeftButton, {}, at(drop));
        checkpoint(QStringLiteral("drag ") + name);
    }

    // The drawn wire into input `pin` of `target`.
    std::optional<CfcWire> wireInto(quint64 target, int pin) const
    {
        for (const CfcWire &wire : m_editor->cfcPolicy().wires())
            if (wire.target == target && wire.pin == pin)
                return wire;
        return std::nullopt;
    }

    QString orderText() const
    {
        QStringList parts;
        for (quint64 id : executionOrder(m_editor->elements())) {
            const auto *block = std::get_if<model::Block>(element(id));
            const auto *out = std::get_if<model::OutVariable>(element(id));
            parts << (block ? block->typeName : out ? out->expression : QStringLiteral("?"));
        }
        return parts.join(QLatin1Char(' '));
    }

    // The counter loop, a comparison and a timer, built with the mouse and typed names.
    void buildCounter()
    {
        place({200, 100}, "cfcBox", QStringLiteral("ADD"));
        place({360, 100}, "cfcBox", QStringLiteral("MOVE"));
        place({100, 140}, "cfcInput", QStringLiteral("1"));
        place({500, 100}, "cfcOutput", QStringLiteral("Count"));
        place({200, 240}, "cfcBox", QStringLiteral("GE"));
        place({100, 260}, "cfcInput", QStringLiteral("Count"));
        place({100, 280}, "cfcInput", QStringLiteral("3"));
        place({420, 240}, "cfcBox", QStringLiteral("TON")); // an instance: its name is typed first
        type(QStringLiteral("T1"));
        place({320, 280}, "cfcInput", QStringLiteral("T#30ms"));
        place({560, 260}, "cfcOutput", QStringLiteral("Done"));
        dragWire(outputPin(QStringLiteral("1")), inputPin(QStringLiteral("ADD"), 1), QStringLiteral("1 to ADD"));
        dragWire(outputPin(QStringLiteral("ADD"), QStringLiteral("OUT")), inputPin(QStringLiteral("MOVE"), 0), QStringLiteral("ADD to MOVE"));
        dragWire(outputPin(QStringLiteral("MOVE"), QStringLiteral("OUT")), inputPin(QStringLiteral("Count"), 0), QStringLiteral("MOVE to Count"));
        // The feedback: MOVE's output back into ADD, drawn from the input end this time.
        dragWire(inputPin(QStringLiteral("ADD"), 0), outputPin(QStringLiteral("MOVE"), QStringLiteral("OUT")), QStringLiteral("MOVE to ADD"));
        quint64 countVariable = 0; // the input Count (elementNamed finds the output, placed first)
        for (const model::Element &e : m_editor->elements())
            if (const auto *in = std::get_if<model::InVariable>(&e); in && in->expression == QLatin1String("Count"))
                countVariable = model::header(e).localId;
        const QPointF countOut = cfcOutputPin(*element(countVariable), std::nullopt).value_or(QPointF());
        dragWire(countOut, inputPin(QStringLiteral("GE"), 0), QStringLiteral("Count to GE"));
        dragWire(outputPin(QStringLiteral("3")), inputPin(QStringLiteral("GE"), 1), QStringLiteral("3 to GE"));
        dragWire(outputPin(QStringLiteral("GE"), QStringLiteral("OUT")), inputPin(QStringLiteral("T1"), 0), QStringLiteral("GE to TON"));
        dragWire(outputPin(QStringLiteral("T#30ms")), inputPin(QStringLiteral("T1"), 1), QStringLiteral("time to TON"));
        dragWire(outputPin(QStringLiteral("T1"), QStringLiteral("Q")), inputPin(QStringLiteral("Done"), 0), QStringLiteral("TON to Done"));
    }

    void checkUndoRedo(const model::Project &start)
    {
        std::vector<model::Project> distinct {start};
        for (const model::Project &p : m_after)
            if (!(p == distinct.back()))
                distinct.push_back(p);
        QCOMPARE(m_stack.count(), int(distinct.size()) - 1);
        for (int i = int(distinct.size()) - 2; i >= 0; --i) {
            m_stack.undo();
            QVERIFY2(m_model.project() == distinct[std::size_t(i)],
                qPrintable(QStringLiteral("undo to step %1: %2").arg(i).arg(iec::test::firstDifference(m_model.project(), distinct[std::size_t(i)]))));
        }
        for (std::size_t i = 1; i < distinct.size(); ++i) {
            m_stack.redo();
            QVERIFY2(m_model.project() == distinct[i], qPrintable(QStringLiteral("redo to step %1").arg(i)));
        }
    }

private Q_SLOTS:
    void counterBuiltWithTheMouseRunsInItsOrder()
    {
        open(cfcProject());
        const model::Project start = m_model.project();
        buildCounter();
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        QCOMPARE(m_editor->elements().size(), std::size_t(10));
        // Every wire drawn, none red; the feedback wire goes round the boxes.
        QCOMPARE(m_editor->cfcPolicy().wires().size(), std::size_t(9));
        for (const CfcWire &wire : m_editor->cfcPolicy().wires())
            QVERIFY(!wire.broken);
        const auto feedback = wireInto(named(QStringLiteral("ADD")), 0);
        QVERIFY(feedback);
        QVERIFY(feedback->points.size() >= 6);
        QCOMPARE(std::get<model::Block>(*element(named(QStringLiteral("T1")))).instanceName, std::optional(QStringLiteral("T1")));

        // Output Count dragged right against MOVE: no room, a red straight wire; back: routed.
        const quint64 count = named(QStringLiteral("Count"));
        const QRectF move = cfcRect(*element(named(QStringLiteral("MOVE"))));
        dragElement(QStringLiteral("Count"), QPointF(move.right() + 10, 100));
        QVERIFY(wireInto(count, 0));
        QVERIFY(wireInto(count, 0)->broken);
        dragElement(QStringLiteral("Count"), QPointF(500, 100));
        QVERIFY(!wireInto(count, 0)->broken);
        QCOMPARE(model::header(*element(count)).position, (model::Position {500, 100}));
        const bool redDrawn = std::ranges::any_of(m_editor->scene()->items(), [](QGraphicsItem *item) {
            const auto *wire = qgraphicsitem_cast<editors::WireItem *>(item);
            return wire && wire->isBroken();
        });
        QVERIFY(!redDrawn);

        // By data flow: GE reads the variable Count, so it needs nothing drawn before it; the loop
        // is entered at ADD, which reads MOVE of the scan before.
        QVERIFY(trigger("cfcOrderDataFlow"));
        QCOMPARE(orderText(), QStringLiteral("GE TON Done ADD MOVE Count"));
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        // Count goes up by one a scan; GE sees the Count of the scan before (it runs first);
        // the timer is on for 30 ms (three scans) before Done.
        const QString counted = trace(m_model.project(), 9);
        QCOMPARE(counted, QStringLiteral("1/FALSE 2/FALSE 3/FALSE 4/FALSE 5/FALSE 6/FALSE 7/TRUE 8/TRUE 9/TRUE"));

        // MOVE one earlier: it now runs before ADD and reads ADD of the scan before, so Count
        // lags one scan behind, and so does Done.
        m_editor->select({named(QStringLiteral("MOVE"))});
        QVERIFY(trigger("cfcOrderEarlier"));
        QCOMPARE(orderText(), QStringLiteral("GE TON Done MOVE ADD Count"));
        QCOMPARE(trace(m_model.project(), 9), QStringLiteral("0/FALSE 1/FALSE 2/FALSE 3/FALSE 4/FALSE 5/FALSE 6/FALSE 7/TRUE 8/TRUE"));

        // Saved and read again, it is the same CFC: marked, with its positions and its order.
        const QByteArray bytes = model::plcopen::writeProject(m_model.project());
        const model::plcopen::ReadResult reread = model::plcopen::readProject(bytes);
        QVERIFY(reread.ok);
        QCOMPARE(model::plcopen::writeProject(reread.project), bytes);
        QCOMPARE(editors::editorLanguage(*reread.project.findPou(QStringLiteral("Main"))->body()), editors::EditorLanguage::CFC);
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        checkUndoRedo(start);
    }

    void insertCommandsAreDroppedWhereTheMouseLetsGo()
    {
        // The tool bar's Insert buttons drag their command (kInsertActionMimeType) onto the
        // sheet; the element lands where the drop is, as one undo step.
        open(cfcProject());
        auto *bar = m_editor->findChild<QToolBar *>(QStringLiteral("diagramToolBar"));
        QVERIFY(bar);
        for (const char *id : {"cfcBox", "cfcInput", "cfcOutput", "cfcJump", "cfcLabel", "cfcReturn", "cfcComment"})
            QVERIFY2(bar->widgetForAction(m_editor->action(QLatin1String(id))), id);
        // As a drag does it: the sheet is entered (and says whether it takes the drop), then the
        // drop.
        const auto dropAction = [&](const QByteArray &id, QPointF where) {
            QMimeData mime;
            mime.setData(QString::fromLatin1(editors::kInsertActionMimeType), id);
            QDragEnterEvent enter(at(where), Qt::CopyAction, &mime, Qt::LeftButton, {});
            QApplication::sendEvent(viewport(), &enter);
            if (!enter.isAccepted())
                return false;
            QDropEvent drop(QPointF(at(where)), Qt::CopyAction, &mime, Qt::LeftButton, {});
            QApplication::sendEvent(viewport(), &drop);
            return drop.isAccepted();
        };
        QVERIFY(dropAction("cfcOutput", QPointF(300, 200)));
        type(QStringLiteral("Done"));
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n')) + QLatin1Char(' ') + m_editor->lastMessage()));
        const quint64 done = named(QStringLiteral("Done"));
        QVERIFY(done);
        QCOMPARE(model::header(*element(done)).position, (model::Position {300, 200}));
        QCOMPARE(m_stack.count(), 2); // the output, its name
        // Only Insert commands land: the sheet refuses a dragged Delete.
        m_editor->select({done});
        QVERIFY(!dropAction("cfcDelete", QPointF(100, 100)));
        QCOMPARE(m_stack.count(), 2);
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
    }

    void enEnoComesAndGoesWithItsWires()
    {
        // A TON wired from an input gets EN/ENO (one undo step each way); its wire stays on IN,
        // the box grows by a row and the file says so (width/height for Beremiz); ENO wired to an
        // output loses that wire when EN/ENO go again.
        open(cfcProject());
        const model::Project start = m_model.project();
        place({300, 100}, "cfcBox", QStringLiteral("TON"));
        type(QStringLiteral("T1"));
        place({100, 120}, "cfcInput", QStringLiteral("Start"));
        dragWire(outputPin(QStringLiteral("Start")), inputPin(QStringLiteral("TON"), 0), QStringLiteral("Start to IN"));
        const quint64 ton = named(QStringLiteral("TON"));
        const double height = cfcRect(*element(ton)).height();
        QCOMPARE(model::header(*element(ton)).height, std::optional(height));
        m_editor->select({ton});
        QVERIFY(trigger("cfcEnEno"));
        const auto *block = std::get_if<model::Block>(element(ton));
        QVERIFY(block);
        QCOMPARE(block->inputVariables.front().formalParameter, QStringLiteral("EN"));
        QCOMPARE(block->outputVariables.front().formalParameter, QStringLiteral("ENO"));
        QCOMPARE(block->instanceName, std::optional(QStringLiteral("T1")));
        QVERIFY(wireInto(ton, 1)); // IN, now the second input, still reads Start
        QVERIFY(!wireInto(ton, 0));
        QCOMPARE(model::header(*element(ton)).height, std::optional(height + 20));
        place({500, 100}, "cfcOutput", QStringLiteral("Ok"));
        dragWire(outputPin(QStringLiteral("TON"), QStringLiteral("ENO")), inputPin(QStringLiteral("Ok"), 0), QStringLiteral("ENO to Ok"));
        QVERIFY(wireInto(named(QStringLiteral("Ok")), 0));
        m_editor->select({ton});
        QVERIFY(trigger("cfcEnEno"));
        QCOMPARE(std::get<model::Block>(*element(ton)).inputVariables.front().formalParameter, QStringLiteral("IN"));
        QVERIFY(wireInto(ton, 0));
        QVERIFY(!wireInto(named(QStringLiteral("Ok")), 0));
        // Only a box has EN/ENO.
        m_editor->select({named(QStringLiteral("Ok"))});
        QVERIFY(!m_editor->action(QStringLiteral("cfcEnEno"))->isEnabled());
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        checkUndoRedo(start);
    }

    void codesysBodyIsEditedInItsOwnForm()
    {
        // A CODESYS CFC: the empty ST body carries the diagram in addData.
        model::Project project = cfcProject();
        model::Pou &main = *std::ranges::find_if(project.types.pous, [](const model::Pou &p) { return p.name == QLatin1String("Main"); });
        model::Body body = model::Body::withLanguage(model::BodyLanguage::ST);
        body.addData.push_back({QStringLiteral("http://www.3s-software.com/plcopenxml/cfc"), QStringLiteral("implementation"),
            QStringLiteral("<CFC><inVariable localId=\"1\"><position x=\"5\" y=\"5\"/><connectionPointOut><expression/></connectionPointOut>"
                           "<expression>Count</expression></inVariable>"
                           "<connector localId=\"2\" name=\"\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"1\" formalParameter=\"Count\"/></connectionPointIn></connector>"
                           "<outVariable localId=\"3\" executionOrderId=\"0\"><position x=\"15\" y=\"5\"/><connectionPointIn><relPosition x=\"0\" y=\"0\"/>"
                           "<connection refLocalId=\"2\"/></connectionPointIn><expression>Done</expression></outVariable></CFC>")});
        main.bodies = {body};
        open(project);
        const QByteArray unchanged = model::plcopen::writeProject(m_model.project());
        QCOMPARE(m_editor->elements().size(), std::size_t(2));
        QCOMPARE(m_editor->cfcPolicy().wires().size(), std::size_t(1));
        QCOMPARE(m_editor->cfcPolicy().storage(), std::optional(CfcStorage::Codesys));
        // Opened and looked at: nothing written.
        QCOMPARE(model::plcopen::writeProject(m_model.project()), unchanged);
        // A move is written back into CODESYS's form, on its grid, as one undo step.
        dragElement(QStringLiteral("Done"), QPointF(400, 90));
        QCOMPARE(m_stack.count(), 1);
        const model::Body *now = m_model.body(model::BodyRef {mainId()});
        QCOMPARE(now->language(), model::BodyLanguage::ST);
        const QString content = now->addData.front().content;
        QVERIFY2(content.contains(QLatin1String("<position x=\"20\" y=\"5\"/>")), qPrintable(content));
        QCOMPARE(content.count(QLatin1String("<connector ")), 1);
        // The arrow keys move by CODESYS's grid, also left and up (a smaller step was rounded
        // back onto the same grid point).
        const quint64 done = named(QStringLiteral("Done"));
        m_editor->select({done});
        m_editor->view()->setFocus();
        for (const auto &[key, expected] : {std::pair {Qt::Key_Left, model::Position {380, 90}}, {Qt::Key_Up, model::Position {380, 70}},
                 {Qt::Key_Right, model::Position {400, 70}}, {Qt::Key_Down, model::Position {400, 90}}}) {
            QTest::keyClick(viewport(), key);
            QCOMPARE(model::header(*element(done)).position, expected);
        }
        QCOMPARE(m_stack.count(), 5);
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        for (int i = 0; i < 4; ++i)
            m_stack.undo();
        m_stack.undo();
        QCOMPARE(model::plcopen::writeProject(m_model.project()), unchanged);
        QCOMPARE(m_editor->elements().size(), std::size_t(2));
    }
};

QTEST_MAIN(TestCfcEditor)
#include "tst_cfceditor.moc"
