// The pure parts of the LD editor as tables: networks read from elements, the RunPro commands at
// the cursor (what each leaves, what it refuses), the layout written back, and imported bodies.
#include "editors/ld/ldedits.h"
#include "editors/ld/ldgeometry.h"
#include "editors/ld/ldnetwork.h"
#include "editors/ld/ldwrite.h"
#include "model/body.h"
#include "model/plcopen/reader.h"

#include <QFile>

#include <set>
#include <QTest>

using namespace iec;
using namespace iec::editors::ld;
using iec::editors::BoxSpec;
using model::Element;

namespace {

QString edgePrefix(model::EdgeModifier edge)
{
    return edge == model::EdgeModifier::Rising ? QStringLiteral("P:") : edge == model::EdgeModifier::Falling ? QStringLiteral("N:") : QString();
}

QString elementSignature(const LadderDocument &doc, quint64 id)
{
    const Element *e = doc.element(id);
    if (!e)
        return QStringLiteral("<gone>");
    if (const auto *c = std::get_if<model::Contact>(e))
        return (c->negated ? QStringLiteral("/") : QString()) + edgePrefix(c->edge) + c->variable;
    if (const auto *c = std::get_if<model::Coil>(e)) {
        const QString storage = c->storage == model::StorageModifier::Set ? QStringLiteral("S:")
            : c->storage == model::StorageModifier::Reset                ? QStringLiteral("R:")
                                                                          : QString();
        return QStringLiteral("(") + (c->negated ? QStringLiteral("/") : QString()) + storage + edgePrefix(c->edge) + c->variable + QStringLiteral(")");
    }
    if (const auto *j = std::get_if<model::Jump>(e))
        return QStringLiteral("->") + j->label;
    if (std::holds_alternative<model::Return>(*e))
        return QStringLiteral("RET");
    if (const auto *o = std::get_if<model::OutVariable>(e))
        return QStringLiteral("=") + o->expression;
    if (const auto *b = std::get_if<model::Block>(e)) {
        QStringList sides;
        const RungPins pins = doc.pinsOf(id);
        for (int p = 0; p < int(b->inputVariables.size()); ++p) {
            if (p == pins.input || !b->inputVariables[std::size_t(p)].connectionPointIn)
                continue;
            for (const auto &c : b->inputVariables[std::size_t(p)].connectionPointIn->connections)
                sides << b->inputVariables[std::size_t(p)].formalParameter + QLatin1Char('=') + elementSignature(doc, c.refLocalId);
        }
        const QString name = b->instanceName ? *b->instanceName + QLatin1Char(':') : QString();
        return name + b->typeName + (sides.isEmpty() ? QString() : QLatin1Char('[') + sides.join(QLatin1Char(',')) + QLatin1Char(']'));
    }
    if (const auto *v = std::get_if<model::InVariable>(e))
        return v->expression;
    return QStringLiteral("?");
}

QString rungSignature(const LadderDocument &doc, const RungNode &node)
{
    switch (node.kind) {
    case RungNode::Kind::Element: return elementSignature(doc, node.localId);
    case RungNode::Kind::Series: {
        QStringList parts;
        for (const RungNode &child : node.children)
            parts << rungSignature(doc, child);
        return parts.join(QLatin1Char(' '));
    }
    case RungNode::Kind::Parallel: {
        QStringList parts;
        for (const RungNode &child : node.children)
            parts << rungSignature(doc, child);
        return QLatin1Char('(') + parts.join(QStringLiteral(" | ")) + QLatin1Char(')');
    }
    }
    return {};
}

QString signature(const LadderDocument &doc)
{
    QStringList networks;
    for (const LdNetwork &network : doc.networks) {
        QString text;
        if (network.label)
            text += std::get<model::Label>(*doc.element(network.label)).label + QStringLiteral(": ");
        if (network.comment)
            text += QStringLiteral("#") + std::get<model::Comment>(*doc.element(network.comment)).content.text + QStringLiteral(" ");
        text += network.freehand ? QStringLiteral("<freehand>") : QLatin1Char('[') + rungSignature(doc, network.rung) + QLatin1Char(']');
        networks << text;
    }
    return networks.join(QStringLiteral(" / "));
}

quint64 elementNamed(const LadderDocument &doc, const QString &name)
{
    for (const Element &e : doc.elements) {
        const quint64 id = model::header(e).localId;
        if (elementText(doc, id) == name && !std::holds_alternative<model::Label>(e))
            return id;
    }
    return 0;
}

BoxSpec tonSpec()
{
    return {QStringLiteral("TON"), true, {QStringLiteral("IN"), QStringLiteral("PT")}, {QStringLiteral("Q"), QStringLiteral("ET")}, 0, 0, false};
}

BoxSpec addSpec(bool withEn)
{
    return {QStringLiteral("ADD"), false, {QStringLiteral("IN1"), QStringLiteral("IN2")}, {QStringLiteral("OUT")}, 0, 0, withEn};
}

// The editor's clipboard, for "copy" and "paste".
std::vector<Element> &clipboard()
{
    static std::vector<Element> fragment;
    return fragment;
}

// A small command language: "c A" inserts a contact at the cursor and names it A, "sel A" puts
// the cursor on the element named A ("sel A B": a range), "net 2" on the second network ...
LdEditResult apply(LadderDocument &doc, LdCursor &cursor, const QString &command)
{
    const QStringList words = command.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    const QString verb = words.value(0);
    const QString arg = words.value(1);
    const auto named = [&](LdEditResult result) {
        if (result.ok() && !arg.isEmpty() && result.cursor.kind == LdCursor::Kind::Element)
            setElementText(doc, result.cursor.element(), arg);
        return result;
    };
    if (verb == QLatin1String("sel")) {
        LdCursor c {LdCursor::Kind::Element, 0, {}, {}};
        for (const QString &name : words.mid(1))
            c.elements.push_back(elementNamed(doc, name));
        c.network = doc.networkOf(c.element());
        return {{}, c};
    }
    if (verb == QLatin1String("net"))
        return {{}, LdCursor::atNetwork(arg.toInt() - 1)};
    if (verb == QLatin1String("gap")) { // "gap 2" or "gap 1.0:1": series path and gap index
        const QStringList parts = arg.split(QLatin1Char(':'));
        WirePoint point;
        if (parts.size() == 2)
            for (const QString &step : parts[0].split(QLatin1Char('.')))
                point.path.push_back(step.toInt());
        point.index = parts.back().toInt();
        return {{}, LdCursor::atWire(cursor.network, point)};
    }
    if (verb == QLatin1String("after"))
        return insertNetwork(doc, cursor, true);
    if (verb == QLatin1String("before"))
        return insertNetwork(doc, cursor, false);
    if (verb == QLatin1String("c"))
        return named(insertContact(doc, cursor));
    if (verb == QLatin1String("p"))
        return named(insertParallelContact(doc, cursor, true));
    if (verb == QLatin1String("pa"))
        return named(insertParallelContact(doc, cursor, false));
    if (verb == QLatin1String("coil"))
        return named(insertCoil(doc, cursor));
    if (verb == QLatin1String("jump"))
        return insertJump(doc, cursor, arg);
    if (verb == QLatin1String("ret"))
        return insertReturn(doc, cursor);
    if (verb == QLatin1String("ton"))
        return named(insertBox(doc, cursor, tonSpec()));
    if (verb == QLatin1String("add"))
        return insertBox(doc, cursor, addSpec(false));
    if (verb == QLatin1String("adden"))
        return insertBox(doc, cursor, addSpec(true));
    if (verb == QLatin1String("input"))
        return insertBoxInput(doc, cursor);
    if (verb == QLatin1String("assign"))
        return named(insertBoxAssignment(doc, cursor));
    if (verb == QLatin1String("op"))
        return insertOperatorAtInput(doc, cursor, {QStringLiteral("AND"), false, {QStringLiteral("IN1"), QStringLiteral("IN2")}, {QStringLiteral("OUT")}, 0, 0, false});
    if (verb == QLatin1String("text"))
        return setElementText(doc, cursor.element(), arg);
    if (verb == QLatin1String("neg"))
        return toggleNegation(doc, cursor);
    if (verb == QLatin1String("sr"))
        return cycleSetReset(doc, cursor);
    if (verb == QLatin1String("edge"))
        return cycleEdge(doc, cursor);
    if (verb == QLatin1String("del"))
        return deleteAtCursor(doc, cursor);
    if (verb == QLatin1String("label"))
        return setNetworkLabel(doc, cursor.network, arg);
    if (verb == QLatin1String("comment"))
        return setNetworkComment(doc, cursor.network, words.mid(1).join(QLatin1Char(' ')));
    if (verb == QLatin1String("copy")) {
        QString error;
        clipboard() = copyAtCursor(doc, cursor, &error);
        return {error, cursor};
    }
    if (verb.startsWith(QLatin1String("paste"))) {
        const PasteMode mode = verb == QLatin1String("pastebelow") ? PasteMode::Below
            : verb == QLatin1String("pasteabove")                 ? PasteMode::Above
                                                                   : PasteMode::After;
        // The framework's clipboard hands out fresh localIds; here the document renumbers.
        return pasteFragment(doc, cursor, clipboard(), mode);
    }
    return {QStringLiteral("unknown command ") + verb, cursor};
}

// Runs the commands on an empty body (one empty network), writing the document back after each
// as the editor does; returns the signature read back from the elements alone, or the first
// refusal.
QString run(const QStringList &commands, LadderDocument *out = nullptr)
{
    LadderDocument doc = readLadder({});
    LdCursor cursor = LdCursor::atNetwork(0);
    insertNetwork(doc, cursor, true);
    writeLadder(doc);
    for (const QString &command : commands) {
        const LdEditResult result = apply(doc, cursor, command);
        if (!result.ok())
            return QStringLiteral("refused: ") + result.error;
        cursor = result.cursor;
        writeLadder(doc);
        const QString before = signature(doc);
        doc = readLadder(doc.elements);
        if (signature(doc) != before)
            return QStringLiteral("reread differs after '%1': %2 vs %3").arg(command, signature(doc), before);
        cursor = validCursor(doc, cursor);
    }
    if (out)
        *out = doc;
    return signature(doc);
}

} // namespace

class TestLdStructure : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void commands_data()
    {
        QTest::addColumn<QStringList>("commands");
        QTest::addColumn<QString>("expected");
        const auto row = [](const char *name, const QString &commands, const QString &expected) {
            QTest::newRow(name) << commands.split(QLatin1Char(';'), Qt::SkipEmptyParts) << expected;
        };
        row("empty network", "", "[]");
        row("contact at network", "c Start", "[Start]");
        row("coil at network", "coil Motor", "[(Motor)]");
        row("contact before the coil", "coil Motor;net 1;c Start", "[Start (Motor)]");
        row("series contact goes left of cursor", "coil Motor;net 1;c B;sel B;c A", "[A B (Motor)]");
        row("start/stop seal-in", "coil Motor;net 1;c Start;sel Start;p Motor;sel Start;c x;sel x;del;net 1;c Stop;sel Stop;neg",
            "[(Start | Motor) /Stop (Motor)]");
        row("parallel above", "c A;sel A;pa B", "[(B | A)]");
        row("parallel around a range", "c A;sel A;c X;sel A;c Y;sel X A;p B", "[(X Y A | B)]");
        row("parallel refused at a coil", "coil Q;sel Q;p A", "refused: A parallel contact goes around contacts and boxes; for another output use Coil.");
        row("second coil goes parallel", "c A;coil Q1;coil Q2", "[A ((Q1) | (Q2))]");
        row("third coil below the cursor's", "c A;coil Q1;coil Q2;sel Q1;coil Q3", "[A ((Q1) | (Q3) | (Q2))]");
        row("contact before a parallel coil", "c A;coil Q1;coil Q2;sel Q2;c B", "[A ((Q1) | B (Q2))]");
        row("set reset cycle", "coil Q;sel Q;sr", "[(S:Q)]");
        row("set reset cycle twice", "coil Q;sel Q;sr;sr", "[(R:Q)]");
        row("set reset back to normal", "coil Q;sel Q;sr;sr;sr", "[(Q)]");
        row("negated coil", "coil Q;sel Q;neg", "[(/Q)]");
        row("edges", "c A;sel A;edge;coil Q;sel Q;edge;edge", "[P:A (N:Q)]");
        row("jump after a contact", "c Cond;jump Skip", "[Cond ->Skip]");
        row("return", "c Done;ret", "[Done RET]");
        row("timer inline", "coil Done;net 1;c Start;net 1;ton T1", "[Start T1:TON[PT=???] (Done)]");
        row("box goes left of the cursor", "c Start;ton T1", "[T1:TON[PT=???] Start]");
        row("timer preset typed", "coil Done;net 1;c Start;net 1;ton T1;sel ???;text T#5s", "[Start T1:TON[PT=T#5s] (Done)]");
        row("box with EN", "coil Q;net 1;c A;net 1;adden", "[A ADD[IN1=???,IN2=???] (Q)]");
        row("box input added", "c A;net 1;adden;input", "[A ADD[IN1=???,IN2=???,IN3=???]]");
        row("operator at a box input", "c A;net 1;adden;sel ???;text X;sel X;op", "[A ADD[IN1=AND[IN1=X,IN2=???],IN2=???]]");
        row("assignment on a box output", "c A;net 1;adden;assign Sum", "[A ADD[IN1=???,IN2=???]]");
        row("delete a contact", "c A;c B;sel B;del", "[A]");
        row("delete the last branch element unwraps", "c A;sel A;p B;sel B;del", "[A]");
        row("delete a box takes its variables", "c A;net 1;ton T1;coil Q;sel T1;del", "[A (Q)]");
        row("delete a side variable empties it", "c A;net 1;ton T1;sel ???;text PT1;sel PT1;del", "[A T1:TON[PT=???]]");
        row("network after", "c A;after;c B", "[A] / [B]");
        row("network before", "c A;before;c B", "[B] / [A]");
        row("delete a network", "c A;after;c B;net 1;del", "[B]");
        row("label and comment", "c A;label Skip;comment hello", "Skip: #hello [A]");
        row("duplicate label refused", "label L;after;label L",
            "refused: Network 1 has the label L already: labels name one network each.");
        row("wire point insert", "c A;c B;gap 1;c X", "[B X A]");
        row("copy and paste a contact after", "c A;coil Q;sel A;copy;paste", "[A A (Q)]");
        row("paste below", "c A;coil Q;sel A;copy;c B;sel B;pastebelow", "[(B | A) A (Q)]");
        row("copy and paste a network", "c A;coil Q;net 1;copy;paste", "[A (Q)] / [A (Q)]");
        row("paste range with a box", "c A;net 1;ton T1;sel T1;copy;sel A;paste", "[A T1:TON[PT=???] T1:TON[PT=???]]");
    }
    void commands()
    {
        QFETCH(QStringList, commands);
        QFETCH(QString, expected);
        QCOMPARE(run(commands), expected);
    }

    // Every network keeps to its own band, rails span the rung, no two elements overlap.
    void layoutKeepsNetworksApart()
    {
        LadderDocument doc;
        QCOMPARE(run(QStringLiteral("c Start;sel Start;p Motor;net 1;c Stop;coil Motor;coil Lamp;after;c A;net 2;ton T1;coil B;after;label L;c C;jump L")
                         .split(QLatin1Char(';')),
                     &doc),
            QStringLiteral("[(Start | Motor) Stop ((Motor) | (Lamp))] / [A T1:TON[PT=???] (B)] / L: [C ->L]"));
        const std::vector<NetworkGeometry> layout = layoutLadder(doc);
        QCOMPARE(layout.size(), std::size_t(3));
        for (std::size_t n = 0; n + 1 < layout.size(); ++n)
            QCOMPARE(layout[n].top + layout[n].height, layout[n + 1].top);
        for (const NetworkGeometry &g : layout) {
            std::vector<QRectF> rects;
            for (const auto &[id, rect] : g.rects) {
                QVERIFY(rect.top() >= g.top && rect.bottom() <= g.top + g.height);
                for (const QRectF &other : rects)
                    QVERIFY2(!rect.intersects(other), "two elements overlap");
                rects.push_back(rect);
            }
            for (const WireRun &wire : g.wires)
                for (qsizetype i = 1; i < wire.points.size(); ++i)
                    QVERIFY2(wire.points[i - 1].x() == wire.points[i].x() || wire.points[i - 1].y() == wire.points[i].y(),
                        "wires run orthogonally");
        }
        // Both coils end at the right rail, one above the other.
        quint64 motorCoil = 0;
        quint64 lampCoil = 0;
        for (const Element &e : doc.elements)
            if (const auto *coil = std::get_if<model::Coil>(&e); coil && coil->variable == QLatin1String("Motor"))
                motorCoil = coil->localId;
            else if (coil && coil->variable == QLatin1String("Lamp"))
                lampCoil = coil->localId;
        QCOMPARE(layout[0].rects.at(motorCoil).right(), layout[0].rects.at(lampCoil).right());
        QVERIFY(layout[0].rects.at(motorCoil).top() < layout[0].rects.at(lampCoil).top());
    }

    // The positions written are exactly the layout's; writing twice changes nothing.
    void writingIsStable()
    {
        LadderDocument doc;
        run(QStringLiteral("c A;sel A;p B;coil Q;after;c C;ton T1;coil D").split(QLatin1Char(';')), &doc);
        const std::vector<Element> once = doc.elements;
        writeLadder(doc);
        QVERIFY(doc.elements == once);
        LadderDocument reread = readLadder(once);
        writeLadder(reread);
        QVERIFY(reread.elements == once);
    }

    void railsGoneFromTheBodyAreMadeAnew()
    {
        // The monkey (seed 2, 1,000 gestures on star_delta) reached a network whose rails were no
        // longer in the body; writing it dereferenced them. Now the rails are made anew.
        LadderDocument doc;
        run(QStringLiteral("c A;coil Q").split(QLatin1Char(';')), &doc);
        LdNetwork &network = doc.networks.front();
        doc.remove({network.leftRail, network.rightRail});
        network.leftRail = 9001;
        network.rightRail = 9002;
        writeLadder(doc);
        const auto *left = doc.element(doc.networks.front().leftRail);
        const auto *right = doc.element(doc.networks.front().rightRail);
        QVERIFY(left && std::holds_alternative<model::LeftPowerRail>(*left));
        QVERIFY(right && std::holds_alternative<model::RightPowerRail>(*right));
        QCOMPARE(readLadder(doc.elements).networks.size(), std::size_t(1));
    }

    void cursorMoves()
    {
        LadderDocument doc;
        run(QStringLiteral("c A;c B;coil Q;after;c C").split(QLatin1Char(';')), &doc);
        const std::vector<NetworkGeometry> layout = layoutLadder(doc);
        LdCursor cursor = LdCursor::atElement(0, elementNamed(doc, QStringLiteral("B")));
        cursor = moveCursor(doc, layout, cursor, 1, 0); // the wire after B
        QCOMPARE(cursor.kind, LdCursor::Kind::Wire);
        cursor = moveCursor(doc, layout, cursor, 1, 0);
        QCOMPARE(cursor.element(), elementNamed(doc, QStringLiteral("A")));
        cursor = moveCursor(doc, layout, cursor, 0, 1); // down: the next network
        QCOMPARE(cursor.kind, LdCursor::Kind::Network);
        QCOMPARE(cursor.network, 1);
        cursor = moveCursor(doc, layout, cursor, 1, 0);
        QVERIFY(cursor.kind != LdCursor::Kind::Network);
    }

    // Another tool's LD bodies: every network is a rung or shown freehand, never lost.
    void importedBodies_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("pou");
        QTest::addColumn<QString>("expected");
        QTest::newRow("Beremiz first steps (a counter drawn freely)") << "beremiz_first_steps.xml" << "CounterLD" << "<freehand>";
        QTest::newRow("OpenPLC TCP socket") << "openplc_TCP_socket.xml" << "" << "";
    }
    void importedBodies()
    {
        QFETCH(QString, file);
        QFETCH(QString, pou);
        QFETCH(QString, expected);
        const QString path = QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/") + file;
        const model::plcopen::ReadResult read = model::plcopen::readProjectFile(path);
        QVERIFY(read.isProject);
        int bodies = 0;
        for (const model::Pou &p : read.project.types.pous) {
            const auto check = [&](const model::Body &body, const QString &name) {
                if (body.language() != model::BodyLanguage::LD)
                    return;
                ++bodies;
                LadderDocument doc = readLadder(*body.elements(), body.layoutGenerated);
                std::set<quint64> members;
                for (const LdNetwork &network : doc.networks)
                    members.insert(network.members.begin(), network.members.end());
                QCOMPARE(members.size(), body.elements()->size()); // every element belongs to a network
                if (!pou.isEmpty() && name == pou)
                    QCOMPARE(signature(doc), expected);
                // Writing keeps every element and every rung.
                const QString before = signature(doc);
                writeLadder(doc);
                QCOMPARE(signature(readLadder(doc.elements)), before);
            };
            if (p.body())
                check(*p.body(), p.name);
            for (const model::PouPart &action : p.actions)
                check(action.body, p.name + QLatin1Char('.') + action.name);
        }
        QVERIFY(bodies > 0);
    }

    // Beremiz draws one left and one right rail for all networks, with each network's comment
    // above it: the shared rails must not pull every comment into the first network.
    // The id index follows every change of the pool without a full rebuild: after each step every
    // element is found at its place, and removed ones are not found.
    void indexFollowsThePool_data()
    {
        QTest::addColumn<QString>("steps");
        QTest::addColumn<QString>("order");
        QTest::newRow("append") << "add -1, add -1" << "1 2 3 4 5 6 7";
        QTest::newRow("insert at the front") << "add 0" << "6 1 2 3 4 5";
        QTest::newRow("insert in the middle") << "add 2, add 4" << "1 2 6 3 7 4 5";
        QTest::newRow("move forward") << "move 0 3" << "2 3 4 1 5";
        QTest::newRow("move back") << "move 4 1" << "1 5 2 3 4";
        QTest::newRow("move to the same place") << "move 2 2" << "1 2 3 4 5";
        QTest::newRow("remove the first") << "remove 1" << "2 3 4 5";
        QTest::newRow("remove two") << "remove 2, remove 4" << "1 3 5";
        QTest::newRow("remove then add") << "remove 3, add 1" << "1 6 2 4 5";
        QTest::newRow("mixed") << "add 5, move 5 0, remove 2, move 1 3" << "6 3 4 1 5";
    }
    void indexFollowsThePool()
    {
        QFETCH(QString, steps);
        QFETCH(QString, order);
        LadderDocument doc;
        for (int id = 1; id <= 5; ++id) {
            model::Contact contact;
            contact.localId = quint64(id);
            doc.elements.push_back(contact);
        }
        doc.reindex();
        std::set<quint64> removed;
        for (const QString &step : steps.split(QStringLiteral(", "))) {
            const QStringList words = step.split(QLatin1Char(' '));
            if (words[0] == QLatin1String("add"))
                doc.add(model::Contact {}, words[1].toInt());
            else if (words[0] == QLatin1String("move"))
                doc.moveElement(words[1].toInt(), words[2].toInt());
            else {
                doc.remove({words[1].toULongLong()});
                removed.insert(words[1].toULongLong());
            }
            for (std::size_t i = 0; i < doc.elements.size(); ++i) {
                const quint64 id = model::header(doc.elements[i]).localId;
                QCOMPARE(doc.indexOf(id), int(i));
                QCOMPARE(doc.element(id), &doc.elements[i]);
            }
            for (quint64 id : removed)
                QCOMPARE(doc.indexOf(id), -1);
        }
        QStringList ids;
        for (const Element &e : doc.elements)
            ids << QString::number(model::header(e).localId);
        QCOMPARE(ids.join(QLatin1Char(' ')), order);
    }

    void sharedRailsKeepEachNetworksComment()
    {
        const model::plcopen::ReadResult read = model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/star_delta.xml"));
        QVERIFY(read.isProject);
        const LadderDocument doc = readLadder(*read.project.findPou(QStringLiteral("Main"))->body()->elements());
        QCOMPARE(doc.networks.size(), std::size_t(5));
        QStringList comments;
        for (const LdNetwork &network : doc.networks)
            comments << (network.comment ? std::get<model::Comment>(*doc.element(network.comment)).content.text.left(10) : QStringLiteral("-"));
        QCOMPARE(comments.join(QLatin1Char('|')), QStringLiteral("Line conta|Star time:|Star conta|Dead time:|Delta cont"));
    }
};

QTEST_MAIN(TestLdStructure)
#include "tst_ldstructure.moc"
