// The LD editor driven as a user drives it (offscreen): commands from its action table at the
// cursor, names typed into the in-place field, arrow keys. A five-network program built with
// commands only is saved after every command (valid against the TC6 XSD), reloads to an equal
// model, runs like the same program in ST, and every command undoes and redoes exactly.
#include "editors/common/blockitems.h"
#include "editors/common/diagramexport.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/common/inplaceeditor.h"
#include "editors/ld/ldeditor.h"
#include "editors/text/calltext.h"
#include "editors/ld/ldedits.h"
#include "editors/ld/ldscene.h"
#include "editors/ld/ldwrite.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"
#include "tests/model/roundtrip.h"

#include <QAction>
#include <QDir>
#include <QDropEvent>
#include <QMimeData>
#include <QScrollBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace iec;
using namespace iec::editors::ld;

namespace {

const char *const kDeclarations = "VAR Start, Stop, Motor, Lamp, Skip, SetBtn, ResetBtn, Latch, Done : BOOL; T1 : TON; END_VAR";

const char *const kStructuredText = "PROGRAM Main\n"
                                    "VAR Start, Stop, Motor, Lamp, Skip, SetBtn, ResetBtn, Latch, Done : BOOL; T1 : TON; END_VAR\n"
                                    "Motor := (Start OR Motor) AND NOT Stop;\n"
                                    "T1(IN := Motor, PT := T#100ms);\n"
                                    "Lamp := T1.Q;\n"
                                    "IF NOT Skip THEN\n"
                                    "  IF SetBtn THEN Latch := TRUE; END_IF\n"
                                    "  IF ResetBtn THEN Latch := FALSE; END_IF\n"
                                    "END_IF\n"
                                    "IF Done THEN RETURN; END_IF\n"
                                    "END_PROGRAM\n";

model::Project emptyLadderProject()
{
    const QString text = QStringLiteral("PROGRAM Main\n") + QLatin1String(kDeclarations) + QStringLiteral("\nEND_PROGRAM\n");
    auto read = interp::frontend::readIecText(text, QStringLiteral("ld"));
    for (model::Pou &pou : read.project.types.pous)
        if (pou.name == QLatin1String("Main"))
            pou.bodies = {model::Body::withLanguage(model::BodyLanguage::LD)};
    read.project.fileHeader.creationDateTime = QStringLiteral("2026-11-25T10:00:00");
    return read.project;
}

// Inputs per scan and the outputs compared: start pulses, a stop, set/reset with the skip jump
// in between, the return.
QString trace(const std::shared_ptr<const interp::Module> &module)
{
    if (!module)
        return QStringLiteral("does not compile");
    interp::Runtime runtime(module);
    QStringList rows;
    for (int scan = 1; scan <= 30; ++scan) {
        const auto set = [&](const char *name, bool value) {
            runtime.write(QStringLiteral("Main.") + QLatin1String(name), value ? QStringLiteral("TRUE") : QStringLiteral("FALSE"));
        };
        set("Start", scan == 2 || scan == 3 || scan == 24);
        set("Stop", scan >= 16 && scan <= 17);
        set("SetBtn", scan == 13 || scan == 21);
        set("ResetBtn", scan == 15 || scan == 27);
        set("Skip", scan >= 19 && scan <= 22);
        set("Done", scan >= 26);
        if (!runtime.runCycle())
            return QStringLiteral("stopped: ") + (runtime.fault() ? runtime.fault()->toString() : QString());
        QStringList row;
        for (const char *name : {"Motor", "Lamp", "Latch"})
            row << runtime.read(QStringLiteral("Main.") + QLatin1String(name)).value_or(QStringLiteral("?"));
        rows << row.join(QLatin1Char(','));
    }
    return rows.join(QLatin1Char('\n'));
}

QByteArray saved(const model::Project &project)
{
    return model::plcopen::writeProject(project);
}

} // namespace

class TestLdEditor : public QObject
{
    Q_OBJECT

private:
    model::ProjectModel m_model;
    QUndoStack m_stack;
    std::unique_ptr<LdEditor> m_editor;
    std::vector<model::Project> m_after; // the model after each command
    QStringList m_problems;

    model::PouId mainId() const { return m_model.project().findPou(QStringLiteral("Main"))->id; }

    void open()
    {
        m_model.reset(emptyLadderProject());
        m_stack.clear();
        m_editor = std::make_unique<LdEditor>(m_model, model::BodyRef {mainId()}, &m_stack);
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

    void key(Qt::Key key)
    {
        QTest::keyClick(m_editor->view()->viewport(), key);
    }

    void selectNamed(const QString &name)
    {
        m_editor->setCursor(LdCursor::atElement(m_editor->document().networkOf(m_editor->elementNamed(name)), m_editor->elementNamed(name)));
    }

    void buildProgram()
    {
        // 1: start/stop with a seal-in contact.
        trigger("ldNetworkAfter");
        trigger("ldContact");
        type(QStringLiteral("Start"));
        trigger("ldParallelContact");
        type(QStringLiteral("Motor"));
        m_editor->setCursor(LdCursor::atNetwork(0));
        trigger("ldContact");
        type(QStringLiteral("Stop"));
        trigger("ldNegate");
        trigger("ldCoil");
        type(QStringLiteral("Motor"));
        // 2: a timer between a contact and a coil.
        trigger("ldNetworkAfter");
        trigger("ldContact");
        type(QStringLiteral("Motor"));
        key(Qt::Key_Right); // the wire after the contact
        trigger("ldFunctionBlock");
        type(QStringLiteral("TON"));
        type(QStringLiteral("T1"));
        selectNamed(QStringLiteral("???"));
        trigger("ldRename");
        type(QStringLiteral("T#100ms"));
        trigger("ldCoil");
        type(QStringLiteral("Lamp"));
        // 3: a conditional jump over the next network.
        trigger("ldNetworkAfter");
        trigger("ldContact");
        type(QStringLiteral("Skip"));
        QVERIFY(m_editor->insertJump(QStringLiteral("L5")));
        checkpoint(QStringLiteral("jump"));
        // 4: a set/reset coil pair, each with its own contact.
        trigger("ldNetworkAfter");
        trigger("ldCoil");
        type(QStringLiteral("Latch"));
        trigger("ldSetReset");
        trigger("ldCoil");
        type(QStringLiteral("Latch"));
        trigger("ldSetReset");
        trigger("ldSetReset");
        trigger("ldContact");
        type(QStringLiteral("ResetBtn"));
        key(Qt::Key_Up);
        key(Qt::Key_Up);
        selectNamed(QStringLiteral("Latch"));
        trigger("ldContact");
        type(QStringLiteral("SetBtn"));
        // 5: the label the jump goes to, and a return.
        trigger("ldNetworkAfter");
        QVERIFY(m_editor->setNetworkLabel(QStringLiteral("L5")));
        checkpoint(QStringLiteral("label"));
        trigger("ldContact");
        type(QStringLiteral("Done"));
        trigger("ldReturn");
    }

private Q_SLOTS:
    void fiveNetworksRunLikeStructuredText()
    {
        open();
        buildProgram();
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        QCOMPARE(m_editor->document().networks.size(), std::size_t(5));
        // Reloaded from the file, the model is the same.
        const QByteArray bytes = saved(m_model.project());
        model::plcopen::ReadResult reread = model::plcopen::readProject(bytes);
        QVERIFY(reread.ok);
        QCOMPARE(saved(reread.project), bytes);
        // The same trace as the ST program, and not a trivial one.
        interp::Diagnostics diagnostics;
        const QString ld = trace(interp::frontend::compileProject(m_model.project(), diagnostics));
        const QString st = trace(interp::compileText(QString::fromLatin1(kStructuredText), diagnostics));
        QCOMPARE(ld, st);
        QVERIFY2(st.contains(QLatin1String("TRUE,TRUE,TRUE")), qPrintable(st));
        QVERIFY(st.contains(QLatin1String("FALSE,FALSE,FALSE")));
    }

    void everyCommandUndoesAndRedoesExactly()
    {
        open();
        const model::Project start = m_model.project();
        buildProgram();
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
        // Undo step by step back to the start, comparing with what each command left.
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

    // Every LD body (POU, action, transition) of every corpus file opens as networks, draws
    // every variable name it uses, and saving without an edit changes nothing.
    void corpusBodiesOpenDrawAndSaveUnchanged_data()
    {
        QTest::addColumn<QString>("file");
        const QDir corpus(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus"));
        int files = 0;
        for (const QString &name : corpus.entryList({QStringLiteral("*.xml")}, QDir::Files, QDir::Name)) {
            QFile file(corpus.filePath(name));
            if (file.open(QIODevice::ReadOnly) && file.readAll().contains("<LD>")) {
                QTest::newRow(qPrintable(name)) << corpus.filePath(name);
                ++files;
            }
        }
        if (files == 0)
            QSKIP("the PLCopen corpus of shared/ has no LD file");
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
                if (body->language() != model::BodyLanguage::LD)
                    continue;
                QUndoStack stack;
                LdEditor editor(projectModel, ref, &stack);
                editor.show();
                editor.fitToWindow();
                QVERIFY(!editor.document().networks.empty());
                const QString svgPath = dir.filePath(QStringLiteral("body%1.svg").arg(opened));
                QCOMPARE(editors::exportScene(*editor.scene(), svgPath), QString());
                QFile svg(svgPath);
                QVERIFY(svg.open(QIODevice::ReadOnly));
                const QString drawn = QString::fromUtf8(svg.readAll());
                for (const model::Element &element : editor.document().elements) {
                    const QString name = elementText(editor.document(), model::header(element).localId);
                    if (!name.isEmpty())
                        QVERIFY2(drawn.contains(name.toHtmlEscaped()), qPrintable(pou.name + QStringLiteral(": ") + name));
                }
                ++opened;
            }
        }
        QVERIFY(opened > 0);
        QCOMPARE(projectModel.revision(), revision);
        QCOMPARE(saved(projectModel.project()), before);
    }

    void refusesWhileOnline()
    {
        open();
        trigger("ldNetworkAfter");
        interp::RuntimeSnapshot snapshot;
        m_editor->setOnlineSnapshot(&snapshot);
        const quint64 revision = m_model.revision();
        QVERIFY(!m_editor->trigger(QStringLiteral("ldContact")));
        QVERIFY(m_editor->lastMessage().contains(QLatin1String("online")));
        QCOMPARE(m_model.revision(), revision);
        m_editor->setOnlineSnapshot(nullptr);
        QVERIFY(m_editor->trigger(QStringLiteral("ldContact")));
    }

    // Online, closed contacts, energised coils and powered wires are blue.
    void powerFlowOnline()
    {
        open();
        buildProgram();
        interp::RuntimeSnapshot snapshot;
        snapshot.cycle = 7;
        snapshot.values.insert(QStringLiteral("Main.Start"), QStringLiteral("TRUE"));
        snapshot.values.insert(QStringLiteral("Main.Stop"), QStringLiteral("FALSE"));
        snapshot.values.insert(QStringLiteral("Main.Motor"), QStringLiteral("TRUE"));
        m_editor->setOnlineInstance(QStringLiteral("Main"));
        QVERIFY(m_editor->onlineNames().contains(QStringLiteral("Main.Start")));
        QVERIFY(m_editor->onlineNames().contains(QStringLiteral("Main.T1.Q")));
        m_editor->setOnlineSnapshot(&snapshot);
        const auto active = [&](const QString &name) {
            editors::DiagramItem *item = m_editor->scene()->itemFor(m_editor->elementNamed(name));
            return item && item->isActive();
        };
        QVERIFY(active(QStringLiteral("Start")));
        QVERIFY(active(QStringLiteral("Stop"))); // normally closed, Stop FALSE: conducts
        QVERIFY(!active(QStringLiteral("Skip")));
        int powered = 0;
        for (QGraphicsItem *item : m_editor->scene()->items())
            if (auto *wire = qgraphicsitem_cast<editors::WireItem *>(item); wire && wire->isPowered())
                ++powered;
        QVERIFY(powered >= 4);
        m_editor->setOnlineSnapshot(nullptr);
        QVERIFY(!active(QStringLiteral("Start")));
    }

    // A function block dragged from the library pane onto a contact is inserted there (before the
    // contact, as the F command does at that cursor) in one undo step; online the drop is refused.
    void libraryDropInsertsABox()
    {
        open();
        trigger("ldNetworkAfter");
        trigger("ldContact");
        type(QStringLiteral("Start"));
        trigger("ldCoil");
        type(QStringLiteral("Motor"));
        const auto dropOn = [&](const QString &name) {
            const editors::DiagramItem *target = m_editor->scene()->itemFor(m_editor->elementNamed(name));
            const QPointF at = m_editor->view()->mapFromScene(target->frame().center());
            QMimeData data;
            data.setData(QString::fromLatin1(editors::kPouMimeType), QByteArrayLiteral("TON"));
            // As a drag does: an enter (which makes the viewport the drop target), then the drop.
            QDragEnterEvent enter(at.toPoint(), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
            QCoreApplication::sendEvent(m_editor->view()->viewport(), &enter);
            if (!enter.isAccepted())
                return false;
            QDropEvent drop(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
            QCoreApplication::sendEvent(m_editor->view()->viewport(), &drop);
            return drop.isAccepted();
        };
        const int steps = m_stack.count();
        QVERIFY(dropOn(QStringLiteral("Start")));
        QCOMPARE(m_stack.count(), steps + 1);
        const LadderDocument &doc = m_editor->document();
        QStringList rung;
        for (quint64 id : rungElements(doc.networks.front().rung)) {
            const model::Element *e = doc.element(id);
            const auto *block = std::get_if<model::Block>(e);
            rung << (block ? block->typeName : elementText(doc, id));
        }
        QCOMPARE(rung.join(QLatin1Char(' ')), QStringLiteral("TON Start Motor"));
        if (editors::InPlaceEditor *field = m_editor->inPlaceEditor())
            field->cancel();

        interp::RuntimeSnapshot snapshot;
        m_editor->setOnlineInstance(QStringLiteral("Main"));
        m_editor->setOnlineSnapshot(&snapshot);
        const model::Project before = m_model.project();
        QVERIFY(dropOn(QStringLiteral("Start")) == false);
        QCOMPARE(m_stack.count(), steps + 1);
        QVERIFY(m_model.project() == before);
        m_editor->setOnlineSnapshot(nullptr);
    }

    // A long body: the overlay paints the networks on screen only (a body of 1,000 networks must
    // repaint in milliseconds), and what scrolls into view gets the values of the last snapshot,
    // also when no new one comes (the program halted or stepped one cycle).
    void onlineValuesFollowTheScroll()
    {
        LadderDocument doc = readLadder({});
        for (int n = 0; n < 40; ++n) {
            const LdCursor at = insertNetwork(doc, LdCursor::atNetwork(n - 1), true).cursor;
            setElementText(doc, insertContact(doc, at).cursor.element(), QStringLiteral("C%1").arg(n));
        }
        writeLadder(doc);
        model::Project project = emptyLadderProject();
        for (model::Pou &pou : project.types.pous)
            if (pou.name == QLatin1String("Main"))
                *pou.bodies.front().elements() = doc.elements;
        m_model.reset(project);
        m_stack.clear();
        m_editor = std::make_unique<LdEditor>(m_model, model::BodyRef {mainId()}, &m_stack);
        m_editor->resize(1000, 700);
        m_editor->show();
        m_editor->scene()->rebuildIfDirty();
        interp::RuntimeSnapshot snapshot;
        snapshot.cycle = 1;
        for (int n = 0; n < 40; ++n)
            snapshot.values.insert(QStringLiteral("Main.C%1").arg(n), QStringLiteral("TRUE"));
        const auto active = [&](int n) {
            editors::DiagramItem *item = m_editor->scene()->itemFor(m_editor->elementNamed(QStringLiteral("C%1").arg(n)));
            return item && item->isActive();
        };
        m_editor->setOnlineInstance(QStringLiteral("Main"));
        m_editor->setOnlineSnapshot(&snapshot);
        QVERIFY(active(0));
        QVERIFY2(!active(39), "the last network is far below the window: not painted yet");
        QScrollBar *bar = m_editor->view()->verticalScrollBar();
        QVERIFY(bar->maximum() > 0);
        bar->setValue(bar->maximum());
        QVERIFY(active(39));
        QVERIFY(active(0)); // what was shown keeps its state
        m_editor->setOnlineSnapshot(nullptr);
        QVERIFY(!active(0));
        QVERIFY(!active(39));
    }
};

QTEST_MAIN(TestLdEditor)
#include "tst_ldeditor.moc"
