// The FBD editor driven as a user drives it (offscreen): commands from its action table at the
// cursor, names typed into the in-place field, arrow keys and clicks. The seed's pulse generator
// (seed 002 §2, 图 6: two TONs and a negation) built with commands only is saved after every
// command (valid against the TC6 XSD), reloads to an equal model, and runs like the same program
// in ST; an ADD grown to four inputs becomes a MUL with a negated input and an S output; every
// command undoes and redoes exactly; every FBD body of the corpus opens, draws its names and
// saves unchanged.
#include "editors/common/blockitems.h"
#include "editors/common/diagramclipboard.h"
#include "editors/common/diagramexport.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/common/inplaceeditor.h"
#include "editors/fbd/fbdeditor.h"
#include "editors/fbd/fbdscene.h"
#include "editors/fbd/fbdvalues.h"
#include "editors/text/calltext.h"
#include "editors/text/completion.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"
#include "interpreter/runtime/snapshot.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"
#include "tests/model/roundtrip.h"

#include <QDir>
#include <QDropEvent>
#include <QMimeData>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace iec;
using namespace iec::editors::fbd;
using Kind = FbdCursor::Kind;

namespace {

const char *const kDeclarations = "VAR T1, T2 : TON; Pulse, A, B, C, D, Lamp : BOOL; X, Y, Z, W, Sum : INT; END_VAR";

// 图 6: T1 runs while T2 is off, T2 runs while T1 is on; T1.Q is the pulse (1 s off, 2 s on).
const char *const kPulseText = "PROGRAM Main\n"
                               "VAR T1, T2 : TON; Pulse, A, B, C, D, Lamp : BOOL; X, Y, Z, W, Sum : INT; END_VAR\n"
                               "T1(IN := NOT T2.Q, PT := T#1s);\n"
                               "Pulse := T1.Q;\n"
                               "T2(IN := T1.Q, PT := T#2s);\n"
                               "END_PROGRAM\n";

model::Project emptyFbdProject()
{
    const QString text = QStringLiteral("PROGRAM Main\n") + QLatin1String(kDeclarations) + QStringLiteral("\nEND_PROGRAM\n");
    auto read = interp::frontend::readIecText(text, QStringLiteral("fbd"));
    for (model::Pou &pou : read.project.types.pous)
        if (pou.name == QLatin1String("Main"))
            pou.bodies = {model::Body::withLanguage(model::BodyLanguage::FBD)};
    read.project.fileHeader.creationDateTime = QStringLiteral("2026-11-26T10:00:00");
    return read.project;
}

// The pulse and both timers' outputs, scan by scan (10 ms a scan: 4.5 s of program time).
QString pulseTrace(const std::shared_ptr<const interp::Module> &module)
{
    if (!module)
        return QStringLiteral("does not compile");
    interp::Runtime runtime(module);
    QStringList rows;
    for (int scan = 1; scan <= 450; ++scan) {
        if (!runtime.runCycle())
            return QStringLiteral("stopped: ") + (runtime.fault() ? runtime.fault()->toString() : QString());
        QStringList row;
        for (const char *name : {"Pulse", "T1.Q", "T2.Q"})
            row << runtime.read(QStringLiteral("Main.") + QLatin1String(name)).value_or(QStringLiteral("?"));
        rows << row.join(QLatin1Char(','));
    }
    return rows.join(QLatin1Char('\n'));
}

QByteArray saved(const model::Project &project)
{
    return model::plcopen::writeProject(project);
}

const model::Block &blockOf(const FbdDocument &document, quint64 id)
{
    return std::get<model::Block>(*document.element(id));
}

// The declared variables, as the app's provider gives them: a name typed in full is the one Enter
// takes, not a longer standard function that starts with it.
class DeclaredNames : public editors::CompletionProvider
{
public:
    QList<editors::CompletionItem> variables() const override
    {
        QList<editors::CompletionItem> items;
        for (const char *name : {"T1", "T2", "Pulse", "A", "B", "C", "D", "Lamp", "X", "Y", "Z", "W", "Sum"})
            items.push_back({QLatin1String(name), editors::CompletionItem::Kind::Variable, {}, {}});
        return items;
    }
    QList<editors::CompletionItem> members(const QString &) const override { return {}; }
    QList<editors::CompletionItem> pous() const override { return {}; }
};

} // namespace

class TestFbdEditor : public QObject
{
    Q_OBJECT

private:
    model::ProjectModel m_model;
    QUndoStack m_stack;
    std::unique_ptr<FbdEditor> m_editor;
    DeclaredNames m_names;
    std::vector<model::Project> m_after; // the model after each command
    QStringList m_problems;

    model::PouId mainId() const { return m_model.project().findPou(QStringLiteral("Main"))->id; }

    void open()
    {
        m_model.reset(emptyFbdProject());
        m_stack.clear();
        m_editor = std::make_unique<FbdEditor>(m_model, model::BodyRef {mainId()}, &m_stack);
        m_editor->setCompletionProvider(&m_names);
        m_editor->resize(1000, 700);
        m_editor->show();
        m_after.clear();
        m_problems.clear();
    }

    // After a command: the file validates, and the model is remembered for undo/redo.
    void checkpoint(const QString &what)
    {
        const QString errors = iec::test::schemaErrors(saved(m_model.project()));
        if (!errors.isEmpty())
            m_problems << what + QStringLiteral(": ") + errors;
        m_after.push_back(m_model.project());
    }

    bool trigger(const char *id)
    {
        const bool ok = m_editor->trigger(QString::fromLatin1(id));
        if (!ok)
            m_problems << QStringLiteral("%1 refused: %2").arg(QLatin1String(id), m_editor->lastMessage());
        checkpoint(QLatin1String(id));
        return ok;
    }

    // Types into the in-place field the last command opened, and presses Enter.
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

    void escape()
    {
        if (editors::InPlaceEditor *field = m_editor->inPlaceEditor())
            QTest::keyClick(field, Qt::Key_Escape);
    }

    // Puts the cursor on the text of the first element with that text.
    void selectText(const QString &text)
    {
        const quint64 id = m_editor->elementNamed(text);
        if (!id)
            m_problems << QStringLiteral("no element reads '%1'").arg(text);
        m_editor->setCursor(FbdCursor::at(Kind::Text, m_editor->document().networkOf(id), id));
    }

    // The network's last element reading "???" that is an assignment.
    quint64 placeholderAssignment(int network) const
    {
        quint64 found = 0;
        for (quint64 id : m_editor->document().networks[std::size_t(network)].members)
            if (const auto *out = std::get_if<model::OutVariable>(m_editor->document().element(id)); out && out->expression == QLatin1String("???"))
                found = id;
        return found;
    }

    quint64 boxTyped(const QString &type) const
    {
        for (const model::Element &e : m_editor->document().elements)
            if (const auto *block = std::get_if<model::Block>(&e); block && block->typeName == type)
                return model::header(e).localId;
        return 0;
    }

    void buildPulseGenerator()
    {
        // Network 1: T1(IN := NOT T2.Q, PT := T#1s), Pulse := T1.Q.
        trigger("fbdNetworkAfter"); // "??? → ???", typing the input
        type(QStringLiteral("T2.Q"));
        trigger("fbdOperator"); // AND after the input, typing its keyword
        type(QStringLiteral("TON")); // the keyword typed over: a TON, its instance next
        type(QStringLiteral("T1"));
        m_editor->setCursor(FbdCursor::at(Kind::Input, 0, boxTyped(QStringLiteral("TON")), 0));
        trigger("fbdNegate");
        selectText(QStringLiteral("???")); // PT
        trigger("fbdRename");
        type(QStringLiteral("T#1s"));
        m_editor->setCursor(FbdCursor::at(Kind::Text, 0, placeholderAssignment(0)));
        trigger("fbdRename");
        type(QStringLiteral("Pulse"));
        // Network 2: T2(IN := T1.Q, PT := T#2s), no assignment.
        trigger("fbdNetworkAfter");
        type(QStringLiteral("T1.Q"));
        trigger("fbdOperator");
        type(QStringLiteral("TON"));
        type(QStringLiteral("T2"));
        selectText(QStringLiteral("???"));
        trigger("fbdRename");
        type(QStringLiteral("T#2s"));
        m_editor->setCursor(FbdCursor::at(Kind::Crossing, 1, placeholderAssignment(1)));
        trigger("fbdDelete");
    }

    void buildAddToMul()
    {
        trigger("fbdNetworkAfter");
        type(QStringLiteral("X"));
        m_editor->setCursor(FbdCursor::at(Kind::End, 0));
        QVERIFY(m_editor->insertOperator(QStringLiteral("ADD")));
        checkpoint(QStringLiteral("ADD"));
        const quint64 add = boxTyped(QStringLiteral("ADD"));
        QVERIFY(add);
        // The second input: Y. Then one more input last (box selected) and one first (input
        // selected).
        m_editor->setCursor(FbdCursor::at(Kind::Box, 0, add));
        trigger("fbdInput");
        m_editor->setCursor(FbdCursor::at(Kind::Input, 0, add, 0));
        trigger("fbdInput");
        const model::Block &grown = blockOf(m_editor->document(), add);
        QStringList pins;
        for (const auto &v : grown.inputVariables)
            pins << v.formalParameter;
        QVERIFY2(grown.inputVariables.size() == 4, qPrintable(pins.join(QLatin1Char(','))));
        // Name the placeholders W, Y, Z top to bottom (the first was inserted first).
        for (const char *name : {"W", "Y", "Z"}) {
            selectText(QStringLiteral("???"));
            trigger("fbdRename");
            type(QLatin1String(name));
        }
        m_editor->setCursor(FbdCursor::at(Kind::Box, 0, add));
        trigger("fbdRename"); // F2 on the box: its keyword
        type(QStringLiteral("MUL"));
        m_editor->setCursor(FbdCursor::at(Kind::Text, 0, placeholderAssignment(0)));
        trigger("fbdRename");
        type(QStringLiteral("Sum"));
        // A second network for the BOOL part: Lamp S:= A AND NOT B.
        trigger("fbdNetworkAfter");
        type(QStringLiteral("A"));
        trigger("fbdOperator");
        escape(); // keeps AND
        const quint64 andBox = boxTyped(QStringLiteral("AND"));
        m_editor->setCursor(FbdCursor::at(Kind::Input, 1, andBox, 1));
        trigger("fbdNegate");
        selectText(QStringLiteral("???"));
        trigger("fbdRename");
        type(QStringLiteral("B"));
        m_editor->setCursor(FbdCursor::at(Kind::Text, 1, placeholderAssignment(1)));
        trigger("fbdRename");
        type(QStringLiteral("Lamp"));
        trigger("fbdSetReset");
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
            QVERIFY2(m_model.project() == distinct[std::size_t(i)], qPrintable(QStringLiteral("undo to step %1").arg(i)));
        }
        for (std::size_t i = 1; i < distinct.size(); ++i) {
            m_stack.redo();
            QVERIFY2(m_model.project() == distinct[i], qPrintable(QStringLiteral("redo to step %1").arg(i)));
        }
    }

private Q_SLOTS:
    void pulseGeneratorRunsLikeStructuredText()
    {
        open();
        buildPulseGenerator();
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        const FbdDocument &doc = m_editor->document();
        QCOMPARE(doc.networks.size(), std::size_t(2));
        QVERIFY(!doc.networks[0].freehand && !doc.networks[1].freehand);
        const model::Block &t1 = blockOf(doc, doc.networks[0].root);
        QCOMPARE(t1.typeName, QStringLiteral("TON"));
        QCOMPARE(t1.instanceName.value_or(QString()), QStringLiteral("T1"));
        QVERIFY(t1.inputVariables[0].negated);
        // Reloaded from the file, the model is the same.
        const QByteArray bytes = saved(m_model.project());
        model::plcopen::ReadResult reread = model::plcopen::readProject(bytes);
        QVERIFY(reread.ok);
        QCOMPARE(saved(reread.project), bytes);
        // The same trace as the ST program: 1 s off, 2 s on.
        interp::Diagnostics diagnostics;
        const QString fbd = pulseTrace(interp::frontend::compileProject(m_model.project(), diagnostics));
        const QString st = pulseTrace(interp::compileText(QString::fromLatin1(kPulseText), diagnostics));
        QCOMPARE(fbd, st);
        // 1 s off (100 scans of 10 ms), 2 s on, off again.
        const QStringList rows = st.split(QLatin1Char('\n'));
        const qsizetype on = rows.indexOf(QStringLiteral("TRUE,TRUE,FALSE"));
        const qsizetype off = rows.indexOf(QStringLiteral("FALSE,FALSE,FALSE"), on);
        QVERIFY2(on >= 95 && on <= 105, qPrintable(QString::number(on)));
        QVERIFY2(off - on >= 195 && off - on <= 205, qPrintable(QString::number(off - on)));
    }

    void pulseGeneratorUndoesAndRedoesExactly()
    {
        open();
        const model::Project start = m_model.project();
        buildPulseGenerator();
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        checkUndoRedo(start);
    }

    void addGrowsBecomesMulAndUndoesExactly()
    {
        open();
        const model::Project start = m_model.project();
        buildAddToMul();
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        const FbdDocument &doc = m_editor->document();
        const quint64 mul = boxTyped(QStringLiteral("MUL"));
        QVERIFY(mul);
        QVERIFY(!boxTyped(QStringLiteral("ADD")));
        const model::Block &block = blockOf(doc, mul);
        QCOMPARE(block.inputVariables.size(), std::size_t(4));
        QStringList inputs;
        for (int pin = 0; pin < 4; ++pin)
            inputs << elementText(doc, sourceOf(doc, mul, pin)->element);
        QCOMPARE(inputs, QStringList({QStringLiteral("W"), QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")}));
        const quint64 lamp = m_editor->elementNamed(QStringLiteral("Lamp"));
        QCOMPARE(std::get<model::OutVariable>(*doc.element(lamp)).storage, model::StorageModifier::Set);
        const model::Block &andBlock = blockOf(doc, boxTyped(QStringLiteral("AND")));
        QVERIFY(!andBlock.inputVariables[0].negated);
        QVERIFY(andBlock.inputVariables[1].negated);
        // It computes what it shows.
        interp::Diagnostics diagnostics;
        auto module = interp::frontend::compileProject(m_model.project(), diagnostics);
        QStringList messages;
        for (const interp::Diagnostic &d : diagnostics.all())
            messages << d.toString();
        QVERIFY2(module, qPrintable(messages.join(QLatin1Char('\n'))));
        interp::Runtime runtime(module);
        for (const auto &[name, value] : {std::pair {"W", "2"}, {"X", "3"}, {"Y", "4"}, {"Z", "5"}, {"A", "TRUE"}, {"B", "FALSE"}})
            runtime.write(QStringLiteral("Main.") + QLatin1String(name), QLatin1String(value));
        QVERIFY(runtime.runCycle());
        QCOMPARE(runtime.read(QStringLiteral("Main.Sum")).value_or(QString()), QStringLiteral("120"));
        QCOMPARE(runtime.read(QStringLiteral("Main.Lamp")).value_or(QString()), QStringLiteral("TRUE"));
        runtime.write(QStringLiteral("Main.A"), QStringLiteral("FALSE"));
        QVERIFY(runtime.runCycle());
        QCOMPARE(runtime.read(QStringLiteral("Main.Lamp")).value_or(QString()), QStringLiteral("TRUE")); // set, held
        checkUndoRedo(start);
    }

    void arrowsAndClicksMoveTheCursor()
    {
        open();
        buildPulseGenerator();
        const FbdDocument &doc = m_editor->document();
        const quint64 t1 = doc.networks[0].root;
        m_editor->setCursor(FbdCursor::at(Kind::Box, 0, t1));
        QTest::keyClick(m_editor->view()->viewport(), Qt::Key_Left);
        QCOMPARE(m_editor->cursor().kind, Kind::Input);
        QCOMPARE(m_editor->cursor().element, t1);
        QTest::keyClick(m_editor->view()->viewport(), Qt::Key_Left);
        QCOMPARE(m_editor->cursor().kind, Kind::Output); // of the variable that feeds the input
        QTest::keyClick(m_editor->view()->viewport(), Qt::Key_Left);
        QCOMPARE(m_editor->cursor().kind, Kind::Text); // the variable T2.Q
        QCOMPARE(elementText(doc, m_editor->cursor().element), QStringLiteral("T2.Q"));
        QTest::keyClick(m_editor->view()->viewport(), Qt::Key_Down);
        QVERIFY(m_editor->cursor().network >= 0);
        // A click on an input's stub selects that input, not the box.
        const QRectF pin = *cursorRect(m_editor->layout(), FbdCursor::at(Kind::Input, 0, t1, 1));
        const QPoint at = m_editor->view()->mapFromScene(pin.center());
        QTest::mouseClick(m_editor->view()->viewport(), Qt::LeftButton, {}, at);
        QCOMPARE(m_editor->cursor(), FbdCursor::at(Kind::Input, 0, t1, 1));
        // A click on the network's number selects the network.
        const QPoint number = m_editor->view()->mapFromScene(QPointF(10, m_editor->layout()[1].top + 8));
        QTest::mouseClick(m_editor->view()->viewport(), Qt::LeftButton, {}, number);
        QCOMPARE(m_editor->cursor(), FbdCursor::atNetwork(1));
    }

    void cutInputPastedOnAnotherMovesTheBranch()
    {
        open();
        trigger("fbdNetworkAfter");
        type(QStringLiteral("X"));
        m_editor->setCursor(FbdCursor::at(Kind::End, 0));
        QVERIFY(m_editor->insertOperator(QStringLiteral("SUB")));
        const quint64 sub = boxTyped(QStringLiteral("SUB"));
        // In1 gets a MUL branch in front; then the branch is cut and pasted on In2.
        m_editor->setCursor(FbdCursor::at(Kind::Input, 0, sub, 0));
        QVERIFY(m_editor->insertOperator(QStringLiteral("MUL")));
        const quint64 mul = boxTyped(QStringLiteral("MUL"));
        QCOMPARE(sourceOf(m_editor->document(), sub, 0)->element, mul);
        m_editor->setCursor(FbdCursor::at(Kind::Input, 0, sub, 0));
        QVERIFY(m_editor->cut());
        QCOMPARE(elementText(m_editor->document(), sourceOf(m_editor->document(), sub, 0)->element), QStringLiteral("???"));
        m_editor->setCursor(FbdCursor::at(Kind::Input, 0, sub, 1));
        QVERIFY2(m_editor->paste(), qPrintable(m_editor->lastMessage()));
        const FbdDocument &doc = m_editor->document();
        const auto second = sourceOf(doc, sub, 1);
        QVERIFY(second);
        QCOMPARE(blockOf(doc, second->element).typeName, QStringLiteral("MUL"));
        QCOMPARE(doc.networks.size(), std::size_t(1));
        QVERIFY(!doc.networks[0].freehand);
    }

    // A function block dragged from the library and dropped on a network is inserted there (as
    // Operator does at the end of the network): one undo step.
    void libraryDropInsertsABox()
    {
        open();
        trigger("fbdNetworkAfter");
        type(QStringLiteral("A"));
        const editors::DiagramItem *target = m_editor->scene()->itemFor(m_editor->elementNamed(QStringLiteral("A")));
        const QPointF at = m_editor->view()->mapFromScene(target->frame().center());
        QMimeData data;
        data.setData(QString::fromLatin1(editors::kPouMimeType), QByteArrayLiteral("TON"));
        QDragEnterEvent enter(at.toPoint(), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(m_editor->view()->viewport(), &enter);
        QVERIFY(enter.isAccepted());
        const int steps = m_stack.count();
        QDropEvent drop(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(m_editor->view()->viewport(), &drop);
        QVERIFY(drop.isAccepted());
        QCOMPARE(m_stack.count(), steps + 1);
        const FbdDocument &doc = m_editor->document();
        const model::Block &ton = blockOf(doc, doc.networks.front().root);
        QCOMPARE(ton.typeName, QStringLiteral("TON"));
        QCOMPARE(elementText(doc, sourceOf(doc, doc.networks.front().root, 0)->element), QStringLiteral("A"));
        if (editors::InPlaceEditor *field = m_editor->inPlaceEditor())
            field->cancel();
    }

    void onlineShowsValuesAndBlueLines()
    {
        open();
        buildAddToMul();
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        m_editor->setOnlineInstance(QStringLiteral("Main"));
        const QStringList names = m_editor->onlineNames();
        QVERIFY(names.contains(QStringLiteral("Main.A")));
        QVERIFY(names.contains(QStringLiteral("Main.Sum")));
        interp::RuntimeSnapshot snapshot;
        snapshot.cycle = 1;
        for (const auto &[name, value] : {std::pair {"W", "2"}, {"X", "3"}, {"Y", "4"}, {"Z", "5"}, {"A", "TRUE"}, {"B", "FALSE"},
                 {"Sum", "120"}, {"Lamp", "TRUE"}})
            snapshot.values.insert(QStringLiteral("Main.") + QLatin1String(name), QLatin1String(value));
        snapshot.forced.insert(QStringLiteral("MAIN.B"));
        m_editor->setOnlineSnapshot(&snapshot);
        const FbdDocument &doc = m_editor->document();
        auto *a = dynamic_cast<editors::ElementItem *>(m_editor->scene()->itemFor(m_editor->elementNamed(QStringLiteral("A"))));
        QVERIFY(a);
        QCOMPARE(a->onlineText(), QStringLiteral("TRUE"));
        QVERIFY(a->isActive());
        // A AND NOT B is TRUE: the wire from the AND is blue; MUL's output shows 120.
        const quint64 andBox = boxTyped(QStringLiteral("AND"));
        int blue = 0;
        int black = 0;
        for (QGraphicsItem *item : m_editor->scene()->items())
            if (auto *wire = qgraphicsitem_cast<editors::WireItem *>(item)) {
                (wire->isPowered() ? blue : black) += 1;
                const bool fromTrue = wire->source() == andBox || wire->source() == m_editor->elementNamed(QStringLiteral("A"));
                QVERIFY(wire->isPowered() == fromTrue);
            }
        QVERIFY(blue >= 2);
        QVERIFY(black >= 4);
        // A double-click on a variable prepares the opposite value, also with the cursor's frame
        // drawn over it.
        QStringList prepared;
        connect(m_editor.get(), &editors::DiagramEditor::prepareValueRequested, this,
            [&](const QString &name, const QString &literal) { prepared << name + QStringLiteral(" := ") + literal; });
        m_editor->setCursor(FbdCursor::at(Kind::Text, 1, m_editor->elementNamed(QStringLiteral("A"))));
        const QPoint onA = m_editor->view()->mapFromScene(a->frame().center());
        QTest::mouseDClick(m_editor->view()->viewport(), Qt::LeftButton, {}, onA);
        QCOMPARE(prepared, QStringList {QStringLiteral("Main.A := FALSE")});
        // The message says how to write it, and goes once A has the value (not before).
        QVERIFY(m_editor->lastMessage().contains(QLatin1String("Main.A := FALSE")));
        snapshot.cycle = 2;
        m_editor->setOnlineSnapshot(&snapshot);
        QVERIFY(m_editor->lastMessage().contains(QLatin1String("Main.A := FALSE")));
        snapshot.cycle = 3;
        snapshot.values.insert(QStringLiteral("Main.A"), QStringLiteral("FALSE"));
        m_editor->setOnlineSnapshot(&snapshot);
        QCOMPARE(m_editor->lastMessage(), QString());
        // Editing is refused online.
        QVERIFY(!m_editor->trigger(QStringLiteral("fbdOperator")));
        QVERIFY(!m_editor->lastMessage().isEmpty());
        m_editor->setOnlineSnapshot(nullptr);
        QCOMPARE(a->onlineText(), QString());
        Q_UNUSED(doc);
    }

    void functionValuesAreComputed_data()
    {
        QTest::addColumn<QString>("type");
        QTest::addColumn<QStringList>("inputs");
        QTest::addColumn<QString>("result");
        QTest::newRow("and") << "AND" << QStringList {"TRUE", "FALSE"} << "FALSE";
        QTest::newRow("or3") << "OR" << QStringList {"FALSE", "FALSE", "TRUE"} << "TRUE";
        QTest::newRow("xor") << "XOR" << QStringList {"TRUE", "TRUE"} << "FALSE";
        QTest::newRow("not") << "NOT" << QStringList {"FALSE"} << "TRUE";
        QTest::newRow("add int") << "ADD" << QStringList {"2", "3", "4"} << "9";
        QTest::newRow("mul real") << "MUL" << QStringList {"1.5", "2"} << "3.0";
        QTest::newRow("sub") << "SUB" << QStringList {"7", "10"} << "-3";
        QTest::newRow("div int truncates") << "DIV" << QStringList {"7", "2"} << "3";
        QTest::newRow("div by zero unknown") << "DIV" << QStringList {"7", "0"} << "";
        QTest::newRow("gt") << "GT" << QStringList {"5", "3"} << "TRUE";
        QTest::newRow("le") << "LE" << QStringList {"5", "3"} << "FALSE";
        QTest::newRow("eq") << "EQ" << QStringList {"INT#4", "4"} << "TRUE";
        QTest::newRow("sel") << "SEL" << QStringList {"TRUE", "10", "20"} << "20";
        QTest::newRow("limit") << "LIMIT" << QStringList {"0", "150", "100"} << "100";
        QTest::newRow("max") << "MAX" << QStringList {"3", "9", "4"} << "9";
        QTest::newRow("time unknown") << "ADD" << QStringList {"T#1s", "T#2s"} << "";
        QTest::newRow("missing input") << "AND" << QStringList {"TRUE", ""} << "";
        QTest::newRow("unknown function") << "CONCAT" << QStringList {"'a'", "'b'"} << "";
    }
    void functionValuesAreComputed()
    {
        QFETCH(QString, type);
        QFETCH(QStringList, inputs);
        QFETCH(QString, result);
        QCOMPARE(evaluateFunction(type, inputs), result);
    }

    // Every FBD body of every corpus file opens as networks, draws every name it uses, and saving
    // without an edit changes nothing.
    void corpusBodiesOpenDrawAndSaveUnchanged_data()
    {
        QTest::addColumn<QString>("file");
        const QDir corpus(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus"));
        int files = 0;
        for (const QString &name : corpus.entryList({QStringLiteral("*.xml")}, QDir::Files, QDir::Name)) {
            QFile file(corpus.filePath(name));
            if (file.open(QIODevice::ReadOnly) && file.readAll().contains("<FBD>")) {
                QTest::newRow(qPrintable(name)) << corpus.filePath(name);
                ++files;
            }
        }
        if (files == 0)
            QSKIP("the PLCopen corpus of shared/ has no FBD file");
    }
    void corpusBodiesOpenDrawAndSaveUnchanged()
    {
        QFETCH(QString, file);
        model::plcopen::ReadResult read = model::plcopen::readProjectFile(file);
        QVERIFY(read.isProject);
        model::ProjectModel projectModel;
        projectModel.reset(std::move(read.project));
        const QByteArray before = saved(projectModel.project());
        const quint64 revision = projectModel.revision();
        int opened = 0;
        QTemporaryDir dir;
        for (const model::Pou &pou : projectModel.project().types.pous) {
            std::vector<std::pair<model::BodyRef, const model::Body *>> bodies;
            if (pou.body())
                bodies.push_back({model::BodyRef {pou.id}, pou.body()});
            for (const model::PouPart &action : pou.actions)
                bodies.push_back({model::BodyRef {pou.id, model::BodyRef::Part::Action, action.name}, &action.body});
            for (const model::PouPart &transition : pou.transitions)
                bodies.push_back({model::BodyRef {pou.id, model::BodyRef::Part::Transition, transition.name}, &transition.body});
            for (const auto &[ref, body] : bodies) {
                if (editors::editorLanguage(*body) != editors::EditorLanguage::FBD)
                    continue;
                QUndoStack stack;
                FbdEditor editor(projectModel, ref, &stack);
                editor.show();
                editor.fitToWindow();
                QVERIFY(!editor.document().networks.empty());
                const QString svgPath = dir.filePath(QStringLiteral("body%1.svg").arg(opened));
                QCOMPARE(editors::exportScene(*editor.scene(), svgPath), QString());
                QFile svg(svgPath);
                QVERIFY(svg.open(QIODevice::ReadOnly));
                const QString drawn = QString::fromUtf8(svg.readAll());
                for (const model::Element &element : editor.document().elements) {
                    QString name = elementText(editor.document(), model::header(element).localId);
                    if (const auto *block = std::get_if<model::Block>(&element))
                        name = block->typeName;
                    if (!name.isEmpty() && !std::holds_alternative<model::Label>(element))
                        QVERIFY2(drawn.contains(name.toHtmlEscaped()), qPrintable(pou.name + QStringLiteral(": ") + name));
                }
                ++opened;
            }
        }
        QVERIFY(opened > 0);
        QCOMPARE(projectModel.revision(), revision);
        QCOMPARE(saved(projectModel.project()), before);
    }

    // An imported body is edited where the user points, and keeps the rest of the file.
    void codesysBodyIsEditable()
    {
        model::plcopen::ReadResult read = model::plcopen::readProjectFile(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/codesys35sp14_FBDExample.xml"));
        if (!read.isProject)
            QSKIP("the CODESYS FBD example is not in shared/");
        model::ProjectModel projectModel;
        projectModel.reset(std::move(read.project));
        const model::Pou *pou = nullptr;
        for (const model::Pou &p : projectModel.project().types.pous)
            if (p.body() && editors::editorLanguage(*p.body()) == editors::EditorLanguage::FBD)
                pou = &p;
        QVERIFY(pou);
        QUndoStack stack;
        FbdEditor editor(projectModel, model::BodyRef {pou->id}, &stack);
        const FbdDocument &doc = editor.document();
        QVERIFY(doc.networks.size() >= 1);
        QVERIFY(!doc.networks[0].freehand);
        QCOMPARE(doc.unshown.size(), std::size_t(1)); // the implementation attributes
        const std::size_t before = doc.elements.size();
        editor.setCursor(FbdCursor::at(Kind::End, 0));
        QVERIFY2(editor.insertAssignment(), qPrintable(editor.lastMessage()));
        QCOMPARE(editor.document().elements.size(), before + 1);
        QCOMPARE(iec::test::schemaErrors(saved(projectModel.project())), QString());
        // The vendor element is still first, untouched.
        QVERIFY(std::holds_alternative<model::VendorElement>(editor.document().elements.front()));
    }
};

QTEST_MAIN(TestFbdEditor)
#include "tst_fbdeditor.moc"
