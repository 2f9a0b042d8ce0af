// The pure parts of the SFC editor as tables: the structure read from elements, the structured
// edits (what each leaves, what it refuses), the layout and the wire geometry.
#include "editors/sfc/sfcedits.h"
#include "editors/sfc/sfcgeometry.h"
#include "editors/sfc/sfclayout.h"
#include "editors/sfc/sfcstructure.h"
#include "model/body.h"
#include "model/plcopen/reader.h"

#include <QTest>

using namespace iec;
using namespace iec::editors::sfc;
using model::Element;

namespace {

QString signature(const ChartDocument &doc, const Sequence &seq)
{
    QStringList parts;
    for (const Node &node : seq) {
        switch (node.kind) {
        case NodeKind::Step: parts << doc.stepName(node.localId); break;
        case NodeKind::MacroStep: parts << QStringLiteral("M:") + doc.stepName(node.localId); break;
        case NodeKind::Transition: parts << QStringLiteral("t"); break;
        case NodeKind::Jump: {
            const Element *e = doc.element(node.localId);
            parts << QStringLiteral("->") + (e ? std::get<model::JumpStep>(*e).targetName : QStringLiteral("?"));
            break;
        }
        case NodeKind::Selection:
        case NodeKind::Parallel: {
            QStringList branches;
            for (const Sequence &branch : node.branches)
                branches << signature(doc, branch);
            const bool parallel = node.kind == NodeKind::Parallel;
            parts << (parallel ? QStringLiteral("[[") : QStringLiteral("[")) + branches.join(QStringLiteral(" | "))
                    + (parallel ? QStringLiteral("]]") : QStringLiteral("]"));
            break;
        }
        }
    }
    return parts.join(QLatin1Char(' '));
}

// Wires and lays out like the editor, then reads the structure back from the elements alone.
QString roundTrip(ChartDocument &doc)
{
    wireChart(doc);
    layoutChart(doc);
    const ChartDocument reread = readChart(doc.elements);
    return signature(reread, reread.chart.main);
}

// What the previous command selected ("$" in a command).
std::vector<quint64> &previousSelection()
{
    static std::vector<quint64> ids;
    return ids;
}

std::vector<quint64> named(const ChartDocument &doc, const QStringList &names)
{
    std::vector<quint64> ids;
    for (const QString &name : names) {
        if (name == QLatin1String("$")) {
            ids.insert(ids.end(), previousSelection().begin(), previousSelection().end());
        } else if (name.startsWith(QLatin1String("t>"))) { // the transition or divergence after a step
            const quint64 step = *doc.stepNamed(name.mid(2));
            for (const Element &e : doc.elements) {
                std::optional<model::ConnectionPointIn> in;
                if (const auto *t = std::get_if<model::Transition>(&e))
                    in = t->connectionPointIn;
                else if (const auto *d = std::get_if<model::SelectionDivergence>(&e))
                    in = d->connectionPointIn;
                if (in)
                    for (const auto &c : in->connections)
                        if (c.refLocalId == step)
                            ids.push_back(model::header(e).localId);
            }
        } else if (name.startsWith(QLatin1String("j>"))) { // a jump to a step
            for (const Element &e : doc.elements)
                if (const auto *j = std::get_if<model::JumpStep>(&e); j && j->targetName == name.mid(2))
                    ids.push_back(j->localId);
        } else
            ids.push_back(doc.stepNamed(name).value_or(0));
    }
    return ids;
}

// A small command language for the table: "after Init", "alt t>Init", "del Step1 t>Step1", ...
EditResult apply(ChartDocument &doc, const QString &command)
{
    const QStringList words = command.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    const QString verb = words.front();
    const std::vector<quint64> ids = named(doc, words.mid(1));
    if (verb == QLatin1String("after"))
        return insertStepTransition(doc, ids, true);
    if (verb == QLatin1String("before"))
        return insertStepTransition(doc, ids, false);
    if (verb == QLatin1String("alt"))
        return insertAlternativeBranch(doc, ids, true);
    if (verb == QLatin1String("altleft"))
        return insertAlternativeBranch(doc, ids, false);
    if (verb == QLatin1String("par"))
        return insertParallelBranch(doc, ids, true);
    if (verb == QLatin1String("del"))
        return deleteSelection(doc, ids);
    if (verb == QLatin1String("macro"))
        return insertMacroStep(doc, ids, true);
    if (verb.startsWith(QLatin1String("jump:")))
        return insertJump(doc, ids, verb.mid(5));
    if (verb.startsWith(QLatin1String("tjump:")))
        return insertTransitionJump(doc, ids, verb.mid(6));
    return {QStringLiteral("unknown command"), {}};
}

} // namespace

class TestSfcStructure : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void roles()
    {
        QCOMPARE(roleOf(NodeKind::Step), Role::StepLike);
        QCOMPARE(roleOf(NodeKind::MacroStep), Role::StepLike);
        QCOMPARE(roleOf(NodeKind::Parallel), Role::StepLike);
        QCOMPARE(roleOf(NodeKind::Transition), Role::TransitionLike);
        QCOMPARE(roleOf(NodeKind::Selection), Role::TransitionLike);
        QCOMPARE(roleOf(NodeKind::Jump), Role::Jump);
    }

    void edits_data()
    {
        QTest::addColumn<QStringList>("commands");
        QTest::addColumn<QString>("chart");
        QTest::addColumn<QString>("refusal"); // part of the message of the last command; empty: accepted
        const auto row = [](const char *name, QStringList commands, const char *chart, const char *refusal = "") {
            QTest::newRow(name) << commands << QString::fromUtf8(chart) << QString::fromUtf8(refusal);
        };
        row("new chart", {}, "Init t ->Init");
        row("after a step", {"after Init"}, "Init t Step1 t ->Init");
        row("after a transition", {"after t>Init"}, "Init t Step1 t ->Init");
        row("before a transition", {"after Init", "before t>Step1"}, "Init t Step1 t Step2 t ->Init");
        row("before a jump", {"before j>Init"}, "Init t Step1 t ->Init");
        row("before the initial step", {"before Init"}, "Init t ->Init", "initial step");
        row("after a jump", {"after j>Init"}, "Init t ->Init", "follow a jump");
        row("alternative branch", {"alt t>Init"}, "Init [t | t] ->Init");
        row("alternative left", {"altleft t>Init"}, "Init [t | t] ->Init");
        row("alternative on a step", {"alt Init"}, "Init t ->Init", "transition");
        row("third alternative", {"after Init", "alt t>Init", "alt t>Init"}, "Init [t | t | t] Step1 t ->Init");
        row("alternative over a range", {"after Init", "alt t>Init t>Step1"}, "Init [t Step1 t | t] ->Init");
        row("parallel branch", {"after Init", "par Step1"}, "Init t [[Step1 | Step2]] t ->Init");
        row("parallel on a transition", {"par t>Init"}, "Init t ->Init", "step");
        row("step inside a parallel branch", {"after Init", "par Step1", "after Step2"},
            "Init t [[Step1 | Step2 t Step3]] t ->Init");
        row("retarget a jump", {"after Init", "jump:Step1 j>Init"}, "Init t Step1 t ->Step1");
        row("jump must end a chain", {"after Init", "jump:Init t>Init"}, "Init t Step1 t ->Init", "last transition");
        row("jump to nowhere", {"jump:Nowhere j>Init"}, "Init t ->Init", "no step");
        row("alternative ending in jumps", {"after Init", "alt t>Step1 j>Init", "jump:Step1 $"},
            "Init t Step1 [t ->Init | t ->Step1]");
        row("jump on the last transition of one alternative branch", {"after Init", "after Step1", "alt t>Step1", "jump:Init $"},
            "Init t Step1 [t Step2 t ->Init | t ->Init]");
        row("jump on a third alternative branch keeps the join of the other two", {"after Init", "alt t>Init", "alt t>Init", "jump:Step1 $"},
            "Init [t | t | t ->Step1] Step1 t ->Init");
        row("transition-jump", {"del j>Init", "del t>Init", "tjump:Init Init"}, "Init t ->Init");
        row("delete a step with its transition", {"after Init", "del Step1"}, "Init t ->Init");
        row("delete the jump", {"del j>Init"}, "Init t");
        row("delete a lone transition", {"after Init", "del t>Step1"}, "Init t ->Init");
        row("delete a branch dissolves the block", {"alt t>Init", "del $"}, "Init t ->Init");
        row("delete the initial step", {"after Init", "del Init"}, "Init t Step1 t ->Init", "initial step");
        row("macro step", {"macro Init"}, "Init t M:Step1 t ->Init");
    }

    void edits()
    {
        QFETCH(QStringList, commands);
        QFETCH(QString, chart);
        QFETCH(QString, refusal);
        ChartDocument doc;
        QVERIFY(createDefaultChart(doc).ok());
        wireChart(doc);
        layoutChart(doc);
        EditResult last;
        for (const QString &command : commands) {
            doc = readChart(doc.elements);
            last = apply(doc, command);
            previousSelection() = last.select;
            if (!last.ok()) {
                // Only the last command of a row may be refused.
                QVERIFY2(&command == &commands.back(), qPrintable(command + QStringLiteral(": ") + last.error));
                break;
            }
            wireChart(doc);
            layoutChart(doc);
            // Every join the editor writes joins two branches or more (the compiler warns otherwise).
            for (const Element &e : doc.elements) {
                if (const auto *join = std::get_if<model::SelectionConvergence>(&e))
                    QVERIFY2(join->connectionPointIns.size() >= 2, qPrintable(command));
                if (const auto *join = std::get_if<model::SimultaneousConvergence>(&e))
                    QVERIFY2(join->connectionPointIns.size() >= 2, qPrintable(command));
            }
        }
        if (refusal.isEmpty())
            QVERIFY2(last.ok(), qPrintable(last.error));
        else
            QVERIFY2(last.error.contains(refusal), qPrintable(last.error));
        doc = readChart(doc.elements);
        QCOMPARE(roundTrip(doc), chart);
    }

    void wiresBackToAStepBecomeJumps()
    {
        // As Beremiz draws a loop: the last transition wired straight back to the initial step.
        model::Step init;
        init.localId = 1;
        init.name = QStringLiteral("Start");
        init.initialStep = true;
        init.connectionPointIn = model::ConnectionPointIn {};
        init.connectionPointIn->connections.push_back({3});
        model::Transition t;
        t.localId = 2;
        t.connectionPointIn = model::ConnectionPointIn {};
        t.connectionPointIn->connections.push_back({1});
        model::Step run;
        run.localId = 4;
        run.name = QStringLiteral("Run");
        run.connectionPointIn = model::ConnectionPointIn {};
        run.connectionPointIn->connections.push_back({2});
        model::Transition back;
        back.localId = 3;
        back.connectionPointIn = model::ConnectionPointIn {};
        back.connectionPointIn->connections.push_back({4});
        ChartDocument doc = readChart({init, t, run, back});
        QCOMPARE(doc.chart.main.size(), std::size_t(5));
        QCOMPARE(doc.chart.main.back().wiredTarget, quint64(1));
        QVERIFY(doc.chart.loose.empty());
        QCOMPARE(roundTrip(doc), QStringLiteral("Start t Run t ->Start"));
    }

    void unplacedChartsKeepTheirBranchOrder()
    {
        // CODESYS writes every position as (0,0): branches then come in file order.
        ChartDocument doc;
        QVERIFY(createDefaultChart(doc).ok());
        wireChart(doc);
        QVERIFY(apply(doc, QStringLiteral("alt t>Init")).ok());
        wireChart(doc);
        for (Element &e : doc.elements)
            model::header(e).position = {0, 0};
        const ChartDocument reread = readChart(doc.elements);
        QCOMPARE(signature(reread, reread.chart.main), QStringLiteral("Init [t | t] ->Init"));
    }

    void importedChartsAreRead_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("pou");
        QTest::addColumn<QString>("chart");
        QTest::newRow("CODESYS, unplaced") << QStringLiteral("codesys35sp18_sfc_test.xml") << QStringLiteral("PLC_PRG")
                                           << QStringLiteral("Init [t Step0 t | t Step7 t] Step4 [t Step8 t ->Step0 | "
                                                             "t Step9 t ->Step7 | t Step10 t | t Step11 t] ->Init");
        QTest::newRow("Beremiz, placed") << QStringLiteral("beremiz_first_steps.xml") << QStringLiteral("CounterSFC")
                                         << QStringLiteral("Start [t Count t | t ResetCounter t] ->Start");
    }

    void importedChartsAreRead()
    {
        QFETCH(QString, file);
        QFETCH(QString, pou);
        QFETCH(QString, chart);
        const auto read = model::plcopen::readProjectFile(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/") + file);
        if (read.fileError)
            QSKIP("the PLCopen corpus of shared/ is not there");
        const model::Pou *found = read.project.findPou(pou);
        QVERIFY(found);
        ChartDocument doc = readChart(*found->body()->elements());
        QStringList loose;
        for (const Sequence &chain : doc.chart.loose)
            loose << signature(doc, chain);
        QCOMPARE(loose.join(QStringLiteral("; ")), QString());
        QCOMPARE(roundTrip(doc), chart);
        // Laid out, nothing overlaps.
        QList<QRectF> frames;
        for (const Element &e : doc.elements)
            frames << elementRect(e);
        for (qsizetype i = 0; i < frames.size(); ++i)
            for (qsizetype j = i + 1; j < frames.size(); ++j)
                QVERIFY2(!frames[i].intersects(frames[j]), qPrintable(QStringLiteral("%1 / %2").arg(i).arg(j)));
    }

    void stepWidths_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("width");
        QTest::newRow("short") << QStringLiteral("S1") << 80.0;
        QTest::newRow("long") << QStringLiteral("WaitForTheLevel") << 130.0;
    }

    void stepWidths()
    {
        QFETCH(QString, name);
        QFETCH(double, width);
        QCOMPARE(stepWidth(name), width);
    }

    void wires_data()
    {
        QTest::addColumn<QRectF>("source");
        QTest::addColumn<QRectF>("target");
        QTest::addColumn<QList<QPointF>>("line");
        QTest::newRow("straight down") << QRectF(0, 0, 80, 32) << QRectF(28, 50, 24, 4)
                                       << QList<QPointF> {{40, 32}, {40, 50}};
        QTest::newRow("bent") << QRectF(0, 0, 80, 32) << QRectF(100, 60, 24, 4)
                              << QList<QPointF> {{40, 32}, {40, 46}, {112, 46}, {112, 60}};
    }

    void wires()
    {
        QFETCH(QRectF, source);
        QFETCH(QRectF, target);
        QFETCH(QList<QPointF>, line);
        model::Step step;
        step.position = {source.x(), source.y()};
        step.width = source.width();
        step.height = source.height();
        model::Transition transition;
        transition.position = {target.x(), target.y()};
        transition.width = target.width();
        transition.height = target.height();
        QCOMPARE(wirePolyline(step, transition), line);
    }

    void wireIntoABarMeetsItStraight()
    {
        model::Transition transition;
        transition.position = {188, 100};
        transition.width = 24;
        transition.height = 4;
        model::SelectionConvergence bar;
        bar.position = {50, 150};
        bar.width = 200;
        bar.height = 1;
        QCOMPARE(wirePolyline(transition, bar), (QList<QPointF> {{200, 104}, {200, 150}}));
    }

    void layoutPutsBranchesSideBySide()
    {
        ChartDocument doc;
        QVERIFY(createDefaultChart(doc).ok());
        wireChart(doc);
        QVERIFY(apply(doc, QStringLiteral("after Init")).ok());
        wireChart(doc);
        QVERIFY(apply(doc, QStringLiteral("par Step1")).ok());
        wireChart(doc);
        layoutChart(doc);
        const QRectF step1 = elementRect(*doc.element(*doc.stepNamed(QStringLiteral("Step1"))));
        const QRectF step2 = elementRect(*doc.element(*doc.stepNamed(QStringLiteral("Step2"))));
        const QRectF init = elementRect(*doc.element(*doc.stepNamed(QStringLiteral("Init"))));
        QCOMPARE(step1.top(), step2.top());
        QVERIFY(step2.left() > step1.right());
        QCOMPARE(step1.center().x(), init.center().x()); // the first branch continues the column
        QCOMPARE(init.topLeft(), QPointF(kMargin, kMargin));
    }
};

QTEST_MAIN(TestSfcStructure)
#include "tst_sfcstructure.moc"
