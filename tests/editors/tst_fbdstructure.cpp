// The FBD commands as pure functions (editors/fbd/fbdedits.h), as a table: each row runs a small
// script of commands at the cursor on an empty body and compares the networks it leaves, written
// as expressions ("Q := AND(A, NOT B)"), with what the seed (002 §2) says the command does. The
// documents are written back and read again after every command, as the editor does, so a
// command that breaks the tree or the file order shows.
#include "editors/fbd/fbdedits.h"
#include "editors/fbd/fbdwrite.h"

#include <QTest>

using namespace iec;
using namespace iec::editors::fbd;
using iec::editors::BoxSpec;
using Kind = FbdCursor::Kind;
using model::Element;

namespace {

BoxSpec specFor(const QString &type)
{
    const QString t = type.toUpper();
    if (t == QLatin1String("TON"))
        return {t, true, {QStringLiteral("IN"), QStringLiteral("PT")}, {QStringLiteral("Q"), QStringLiteral("ET")}, 0, 0, false};
    if (t == QLatin1String("NOT"))
        return {t, false, {QStringLiteral("IN")}, {QStringLiteral("OUT")}, 0, 0, false};
    if (t == QLatin1String("SEL"))
        return {t, false, {QStringLiteral("G"), QStringLiteral("IN0"), QStringLiteral("IN1")}, {QStringLiteral("OUT")}, 0, 0, false};
    return {t, false, {QStringLiteral("IN1"), QStringLiteral("IN2")}, {QStringLiteral("OUT")}, 0, 0, false};
}

QString expression(const FbdDocument &doc, Port port, int depth = 0)
{
    const Element *e = doc.element(port.element);
    if (!e || depth > 50)
        return QStringLiteral("?");
    if (const auto *in = std::get_if<model::InVariable>(e))
        return (in->negated ? QStringLiteral("NOT ") : QString()) + in->expression;
    if (const auto *inOut = std::get_if<model::InOutVariable>(e))
        return inOut->expression;
    const auto &block = std::get<model::Block>(*e);
    QStringList args;
    for (int pin = 0; pin < inputCount(*e); ++pin) {
        const auto source = sourceOf(doc, port.element, pin);
        QString arg = source ? expression(doc, *source, depth + 1) : QStringLiteral("_");
        const auto &variable = block.inputVariables[std::size_t(pin)];
        if (variable.edge == model::EdgeModifier::Rising)
            arg = QStringLiteral("R_EDGE ") + arg;
        if (variable.edge == model::EdgeModifier::Falling)
            arg = QStringLiteral("F_EDGE ") + arg;
        if (variable.negated)
            arg = QStringLiteral("NOT ") + arg;
        args << arg;
    }
    QString call = block.typeName + QLatin1Char('(') + args.join(QStringLiteral(", ")) + QLatin1Char(')');
    if (block.instanceName)
        call = *block.instanceName + QLatin1Char(':') + call;
    if (block.outputVariables.size() > 1)
        call += QLatin1Char('.') + block.outputVariables[std::size_t(port.pin)].formalParameter;
    if (port.pin < int(block.outputVariables.size()) && block.outputVariables[std::size_t(port.pin)].negated)
        call = QStringLiteral("NOT ") + call;
    return call;
}

// Every network: its label, then each assignment, jump and return with the expression it takes
// (in file order), or the root's expression when nothing takes it.
QString dump(const FbdDocument &doc)
{
    QStringList networks;
    for (const FbdNetwork &network : doc.networks) {
        QStringList parts;
        if (network.label)
            parts << std::get<model::Label>(*doc.element(network.label)).label + QLatin1Char(':');
        if (network.freehand)
            parts << QStringLiteral("free");
        bool rootTaken = false;
        for (quint64 id : network.members) {
            const Element &e = *doc.element(id);
            if (!isSink(e))
                continue;
            const auto source = sourceOf(doc, id, 0);
            const QString value = source ? expression(doc, *source) : QStringLiteral("_");
            rootTaken = rootTaken || (source && source->element == network.root);
            if (const auto *out = std::get_if<model::OutVariable>(&e)) {
                const QString op = out->storage == model::StorageModifier::Set ? QStringLiteral(" S:= ")
                    : out->storage == model::StorageModifier::Reset            ? QStringLiteral(" R:= ")
                                                                               : QStringLiteral(" := ");
                parts << (out->negated ? QStringLiteral("NOT ") : QString()) + out->expression + op + value;
            } else if (const auto *jump = std::get_if<model::Jump>(&e)) {
                parts << QStringLiteral("JMP ") + jump->label + QStringLiteral(" IF ") + value;
            } else {
                parts << QStringLiteral("RETURN IF ") + value;
            }
        }
        if (!rootTaken && network.root)
            parts << expression(doc, {network.root, 0});
        networks << parts.join(QStringLiteral("; "));
    }
    return networks.join(QStringLiteral(" | "));
}

quint64 findText(const FbdDocument &doc, const QString &text)
{
    for (const Element &e : doc.elements)
        if (elementText(doc, model::header(e).localId) == text)
            return model::header(e).localId;
    return 0;
}

quint64 findBox(const FbdDocument &doc, const QString &type)
{
    for (const Element &e : doc.elements)
        if (const auto *block = std::get_if<model::Block>(&e); block && block->typeName == type)
            return model::header(e).localId;
    return 0;
}

// Runs the script; returns the dump, or "refused: <message>" at the first refusal.
QString run(const QString &script)
{
    FbdDocument doc = readFbd({});
    FbdCursor cursor = FbdCursor::atNetwork(0);
    std::vector<Element> clipboard;
    for (const QString &raw : script.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        const QStringList w = raw.trimmed().split(QLatin1Char(' '), Qt::SkipEmptyParts);
        const QString cmd = w.value(0);
        const int network = std::max(0, doc.networkOf(cursor.element));
        FbdEditResult r {{}, cursor};
        if (cmd == QLatin1String("at")) {
            const QString kind = w.value(1);
            if (kind == QLatin1String("text")) {
                const quint64 id = findText(doc, w.value(2));
                cursor = FbdCursor::at(Kind::Text, doc.networkOf(id), id);
            } else if (kind == QLatin1String("cross")) {
                const quint64 id = findText(doc, w.value(2));
                cursor = FbdCursor::at(Kind::Crossing, doc.networkOf(id), id);
            } else if (kind == QLatin1String("in") || kind == QLatin1String("out") || kind == QLatin1String("box")) {
                const quint64 id = findBox(doc, w.value(2));
                const Kind k = kind == QLatin1String("in") ? Kind::Input : kind == QLatin1String("out") ? Kind::Output : Kind::Box;
                cursor = FbdCursor::at(k, doc.networkOf(id), id, w.value(3).toInt());
            } else if (kind == QLatin1String("assign")) {
                quint64 id = 0;
                for (const Element &e : doc.elements)
                    if (const auto *out = std::get_if<model::OutVariable>(&e); out && !id && out->expression == w.value(2))
                        id = model::header(e).localId;
                cursor = FbdCursor::at(Kind::Crossing, doc.networkOf(id), id);
            } else if (kind == QLatin1String("inst")) {
                const quint64 id = findBox(doc, w.value(2));
                cursor = FbdCursor::at(Kind::Text, doc.networkOf(id), id);
            } else if (kind == QLatin1String("end")) {
                cursor = FbdCursor::at(Kind::End, w.value(2).toInt());
            } else {
                cursor = FbdCursor::atNetwork(w.value(2).toInt());
            }
            continue;
        }
        if (cmd == QLatin1String("net"))
            r = insertNetwork(doc, cursor.kind == Kind::Network ? cursor : FbdCursor::atNetwork(network), true);
        else if (cmd == QLatin1String("type"))
            r = setElementText(doc, cursor.element, w.mid(1).join(QLatin1Char(' ')));
        else if (cmd == QLatin1String("op"))
            r = insertOperator(doc, cursor, specFor(w.value(1)));
        else if (cmd == QLatin1String("input"))
            r = insertInput(doc, cursor);
        else if (cmd == QLatin1String("output"))
            r = insertOutput(doc, cursor);
        else if (cmd == QLatin1String("assign"))
            r = insertAssignment(doc, cursor);
        else if (cmd == QLatin1String("jump"))
            r = insertJump(doc, cursor, w.value(1));
        else if (cmd == QLatin1String("return"))
            r = insertReturn(doc, cursor);
        else if (cmd == QLatin1String("neg"))
            r = toggleNegation(doc, cursor);
        else if (cmd == QLatin1String("sr"))
            r = cycleSetReset(doc, cursor);
        else if (cmd == QLatin1String("edge"))
            r = cycleEdge(doc, cursor);
        else if (cmd == QLatin1String("del"))
            r = deleteAtCursor(doc, cursor);
        else if (cmd == QLatin1String("label"))
            r = setNetworkLabel(doc, cursor.kind == Kind::Network ? cursor.network : network, w.value(1));
        else if (cmd == QLatin1String("copy") || cmd == QLatin1String("cut")) {
            QString error;
            clipboard = copyAtCursor(doc, cursor, &error);
            if (clipboard.empty())
                return QStringLiteral("refused: ") + error;
            if (cmd == QLatin1String("cut"))
                r = deleteAtCursor(doc, cursor);
        } else if (cmd == QLatin1String("paste"))
            r = pasteFragment(doc, cursor, clipboard);
        else
            return QStringLiteral("unknown command ") + cmd;
        if (!r.ok())
            return QStringLiteral("refused: ") + r.error;
        cursor = r.cursor;
        // As the editor does: written back, read again.
        writeFbd(doc);
        doc = readFbd(std::move(doc.elements));
        cursor = validCursor(doc, cursor);
    }
    return dump(doc);
}

} // namespace

class TestFbdStructure : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void commands_data()
    {
        QTest::addColumn<QString>("script");
        QTest::addColumn<QString>("expected");
        // Networks.
        QTest::newRow("a new network assigns ??? to ???") << "net" << "??? := ???";
        QTest::newRow("typed") << "net; type A; at text ???; type Q" << "Q := A";
        QTest::newRow("networks after each other") << "net; type A; net; type B" << "??? := A | ??? := B";
        QTest::newRow("network before") << "net; type A; at net 0; net; type B" << "??? := A | ??? := B";
        QTest::newRow("label") << "net; label L1" << "L1:; ??? := ???";
        // (3) Operator: at the end, before an input, after an output, replacing a box, before a sink.
        QTest::newRow("operator at the end") << "net; type A; at end 0; op AND" << "??? := AND(A, ???)";
        QTest::newRow("operator after an output") << "net; type A; at text A; op OR" << "??? := OR(A, ???)";
        QTest::newRow("operator before an input")
            << "net; type A; at end 0; op AND; at in AND 1; op OR" << "??? := AND(A, OR(???, ???))";
        QTest::newRow("operator replaces a box, keeps wires")
            << "net; type A; at end 0; op AND; at box AND; op XOR" << "??? := XOR(A, ???)";
        QTest::newRow("a smaller box drops extra branches")
            << "net; type A; at end 0; op AND; at box AND; input; at box AND; op NOT" << "??? := NOT(A)";
        QTest::newRow("extensible keeps all") << "net; type A; at end 0; op ADD; at box ADD; input; at box ADD; op MUL"
                                              << "??? := MUL(A, ???, ???)";
        QTest::newRow("operator before an assignment")
            << "net; type A; at text ???; type Q; at cross Q; op NOT" << "Q := NOT(A)";
        QTest::newRow("operator before one of two assignments")
            << "net; type A; at text ???; type Q; at text Q; output; type R; at cross R; op NOT" << "Q := A; R := NOT(A)";
        QTest::newRow("function block") << "net; type A; at end 0; op TON; at inst TON; type T1" << "??? := T1:TON(A, ???).Q";
        // (1) Input: first when an input is selected, last when the box is.
        QTest::newRow("input last") << "net; type A; at end 0; op ADD; at box ADD; input; at in ADD 1; neg"
                                    << "??? := ADD(A, NOT ???, ???)";
        QTest::newRow("input before the selected")
            << "net; type A; at end 0; op ADD; at in ADD 0; input; at in ADD 1; neg" << "??? := ADD(???, NOT A, ???)";
        QTest::newRow("input refused on a fixed box")
            << "net; type A; at end 0; op SEL; at box SEL; input" << "refused: SEL has a fixed number of inputs.";
        // (2), (4)–(6) Output, assignment, jump, return.
        QTest::newRow("output adds an assignment below") << "net; type A; at text ???; type Q; at text Q; output; type R"
                                                         << "Q := A; R := A";
        QTest::newRow("assignment on an inner output")
            << "net; type A; at end 0; op AND; at end 0; op OR; at out AND 0; assign; type M" << "M := AND(A, ???); ??? := OR(AND(A, ???), ???)";
        QTest::newRow("jump at the end") << "net; type A; at end 0; jump L2" << "??? := A; JMP L2 IF A";
        QTest::newRow("return at the end") << "net; type A; at end 0; return" << "??? := A; RETURN IF A";
        // (7) Negate, (8) Set/Reset, edges.
        QTest::newRow("negate an input") << "net; type A; at end 0; op AND; at in AND 1; neg" << "??? := AND(A, NOT ???)";
        QTest::newRow("negate twice") << "net; type A; at end 0; op AND; at in AND 1; neg; neg" << "??? := AND(A, ???)";
        QTest::newRow("negate an output") << "net; type A; at end 0; op AND; at out AND 0; neg" << "??? := NOT AND(A, ???)";
        QTest::newRow("negate an assignment") << "net; type A; at text ???; type Q; at cross Q; neg" << "NOT Q := A";
        QTest::newRow("negate a jump negates what feeds it")
            << "net; type A; at end 0; op AND; at assign ???; del; at end 0; jump L; at cross L; neg"
            << "JMP L IF NOT AND(A, ???)";
        QTest::newRow("set") << "net; type A; at text ???; type Q; at cross Q; sr" << "Q S:= A";
        QTest::newRow("reset") << "net; type A; at text ???; type Q; at cross Q; sr; sr" << "Q R:= A";
        QTest::newRow("set reset normal") << "net; type A; at text ???; type Q; at cross Q; sr; sr; sr" << "Q := A";
        QTest::newRow("set on an output with one assignment")
            << "net; type A; at end 0; op AND; at out AND 0; sr" << "??? S:= AND(A, ???)";
        QTest::newRow("edge rising then falling")
            << "net; type A; at end 0; op AND; at in AND 0; edge; at in AND 1; edge; edge" << "??? := AND(R_EDGE A, F_EDGE ???)";
        // Delete.
        QTest::newRow("delete a box leaves ???") << "net; type A; at end 0; op AND; at end 0; op OR; at box AND; del"
                                                 << "??? := OR(???, ???)";
        QTest::newRow("delete an extensible input") << "net; type A; at end 0; op ADD; at box ADD; input; at in ADD 0; del"
                                                    << "??? := ADD(???, ???)";
        QTest::newRow("delete an assignment") << "net; type A; at text ???; type Q; at text Q; output; type R; at cross Q; del"
                                              << "R := A";
        QTest::newRow("delete a network") << "net; type A; net; type B; at net 0; del" << "??? := B";
        QTest::newRow("delete a variable makes it ???") << "net; type A; at text A; del" << "??? := ???";
        // Cut an input, paste it on another: the branch moves (seed 002 §2 (1)).
        QTest::newRow("cut and paste a branch")
            << "net; type A; at end 0; op AND; at in AND 0; op OR; at in AND 0; cut; at in AND 1; paste"
            << "??? := AND(???, OR(A, ???))";
        QTest::newRow("copy a network and paste it after") << "net; type A; at net 0; copy; paste" << "??? := A | ??? := A";
        QTest::newRow("nothing to copy at the end") << "net; at end 0; copy" << "refused: Select a network, a box or an input to copy.";
    }

    void commands()
    {
        QFETCH(QString, script);
        QFETCH(QString, expected);
        QCOMPARE(run(script), expected);
    }

    // Reading: a graph that is not a tree is shown as drawn; a label belongs to the network below.
    void readsTreesAndGraphs()
    {
        // in1 feeds two boxes: not a tree.
        std::vector<Element> elements;
        model::InVariable in;
        in.localId = 1;
        in.expression = QStringLiteral("A");
        in.connectionPointOut.emplace();
        elements.push_back(in);
        for (quint64 id : {2, 3}) {
            model::OutVariable out;
            out.localId = id;
            out.expression = QStringLiteral("Q%1").arg(id);
            out.connectionPointIn.emplace();
            out.connectionPointIn->connections.push_back({1, {}, {}, {}, {}, {}});
            out.position = {100, double(id) * 30};
            elements.push_back(out);
        }
        FbdDocument doc = readFbd(elements);
        QCOMPARE(doc.networks.size(), std::size_t(1));
        QVERIFY(!doc.networks[0].freehand); // one variable, two assignments: still a tree
        QCOMPARE(dump(doc), QStringLiteral("Q2 := A; Q3 := A"));
        model::Block b1;
        b1.localId = 4;
        b1.typeName = QStringLiteral("NOT");
        model::BlockVariable pin;
        pin.formalParameter = QStringLiteral("IN");
        pin.connectionPointIn.emplace();
        pin.connectionPointIn->connections.push_back({1, {}, {}, {}, {}, {}});
        b1.inputVariables = {pin};
        model::BlockVariable out;
        out.formalParameter = QStringLiteral("OUT");
        out.connectionPointOut.emplace();
        b1.outputVariables = {out};
        model::Block b2 = b1;
        b2.localId = 5;
        elements.push_back(b1);
        elements.push_back(b2);
        doc = readFbd(elements);
        QCOMPARE(doc.networks.size(), std::size_t(1));
        QVERIFY(doc.networks[0].freehand); // A feeds two boxes
        // A label above a tree (its own group, Beremiz draws it so) belongs to the network below.
        model::Label label;
        label.localId = 9;
        label.label = QStringLiteral("L1");
        label.position = {0, -40};
        std::vector<Element> labelled {elements[0], elements[1], label};
        doc = readFbd(labelled);
        QCOMPARE(doc.networks.size(), std::size_t(1));
        QCOMPARE(doc.networks[0].label, quint64(9));
        QCOMPARE(dump(doc), QStringLiteral("L1:; Q2 := A"));
    }
};

QTEST_GUILESS_MAIN(TestFbdStructure)
#include "tst_fbdstructure.moc"
