// The CFC editor's pure parts: CODESYS's form read and written back (editors/cfc/cfcstorage.h),
// where pins stand and how wires run (cfcgeometry.h), and the edits with the execution order
// (cfcedits.h).
#include "editors/cfc/cfcedits.h"
#include "editors/cfc/cfcgeometry.h"
#include "editors/cfc/cfcstorage.h"
#include "editors/common/editorlanguage.h"
#include "model/body.h"

#include <QTest>

using namespace iec;
using namespace iec::editors::cfc;
using model::Element;

namespace {

// A CFC as CODESYS exports it: grid positions, every wire through an anonymous connector (also
// from an input variable, whose name the connection repeats), the order from 0.
const char *const kCodesysCounter =
    "<CFC>"
    "<inVariable localId=\"3\"><position x=\"9\" y=\"14\" /><connectionPointOut><expression /></connectionPointOut><expression>Step</expression></inVariable>"
    "<connector localId=\"2\" name=\"\"><position x=\"0\" y=\"0\" /><connectionPointIn><connection refLocalId=\"3\" formalParameter=\"Step\" /></connectionPointIn></connector>"
    "<block localId=\"1\" executionOrderId=\"0\" typeName=\"ADD\"><position x=\"18\" y=\"13\" />"
    "<inputVariables>"
    "<variable formalParameter=\"In1\"><connectionPointIn><relPosition x=\"0\" y=\"0\" /><connection refLocalId=\"2\" /></connectionPointIn></variable>"
    "<variable formalParameter=\"In2\"><connectionPointIn><relPosition x=\"0\" y=\"1\" /><connection refLocalId=\"0\" /></connectionPointIn></variable>"
    "</inputVariables><inOutVariables />"
    "<outputVariables><variable formalParameter=\"Out1\"><connectionPointOut><relPosition x=\"0\" y=\"0\" /><expression /></connectionPointOut></variable></outputVariables>"
    "<addData><data name=\"http://www.3s-software.com/plcopenxml/cfccalltype\" handleUnknown=\"implementation\"><CallType>operator</CallType></data></addData>"
    "</block>"
    "<connector localId=\"0\" name=\"\"><position x=\"0\" y=\"0\" /><connectionPointIn><connection refLocalId=\"1\" formalParameter=\"Out1\" /></connectionPointIn></connector>"
    "<outVariable localId=\"6\" executionOrderId=\"1\"><position x=\"33\" y=\"14\" /><connectionPointIn><relPosition x=\"0\" y=\"0\" /><connection refLocalId=\"0\" /></connectionPointIn><expression>Count</expression></outVariable>"
    "</CFC>";

const Element *find(const std::vector<Element> &elements, quint64 id)
{
    for (const Element &e : elements)
        if (model::header(e).localId == id)
            return &e;
    return nullptr;
}

model::Connection connectionInto(const std::vector<Element> &elements, quint64 id, int pin)
{
    const Element *e = find(elements, id);
    return e ? model::inputPoints(*e)[std::size_t(pin)]->connections.at(0) : model::Connection {};
}

model::Block box(const QString &type, const QStringList &inputs, const QStringList &outputs, double x, double y)
{
    model::Block block;
    block.typeName = type;
    block.position = {x, y};
    for (const QString &name : inputs) {
        model::BlockVariable v;
        v.formalParameter = name;
        v.connectionPointIn.emplace();
        block.inputVariables.push_back(v);
    }
    for (const QString &name : outputs) {
        model::BlockVariable v;
        v.formalParameter = name;
        v.connectionPointOut.emplace();
        block.outputVariables.push_back(v);
    }
    return block;
}

model::InVariable input(const QString &text, double x, double y)
{
    model::InVariable v;
    v.expression = text;
    v.position = {x, y};
    v.connectionPointOut.emplace();
    return v;
}

model::OutVariable output(const QString &text, double x, double y)
{
    model::OutVariable v;
    v.expression = text;
    v.position = {x, y};
    v.connectionPointIn.emplace();
    return v;
}

// The execution order as "id:number" in element order.
QString orderOf(const std::vector<Element> &elements)
{
    QStringList parts;
    for (const Element &e : elements)
        if (const auto &order = model::header(e).executionOrderId)
            parts << QStringLiteral("%1:%2").arg(model::header(e).localId).arg(*order);
    return parts.join(QLatin1Char(' '));
}

// ADD (1) reads MOVE (2) and 1 (3); MOVE reads ADD; Count (4) reads MOVE: a loop.
std::vector<Element> counterLoop()
{
    std::vector<Element> elements;
    insertElement(elements, box(QStringLiteral("ADD"), {QStringLiteral("IN1"), QStringLiteral("IN2")}, {QStringLiteral("OUT")}, 0, 0), {200, 100});
    insertElement(elements, box(QStringLiteral("MOVE"), {QStringLiteral("IN")}, {QStringLiteral("OUT")}, 0, 0), {340, 100});
    insertElement(elements, input(QStringLiteral("1"), 0, 0), {100, 140});
    insertElement(elements, output(QStringLiteral("Count"), 0, 0), {480, 120});
    connectPins(elements, 2, QStringLiteral("OUT"), 1, 0);
    connectPins(elements, 3, std::nullopt, 1, 1);
    connectPins(elements, 1, QStringLiteral("OUT"), 2, 0);
    connectPins(elements, 2, QStringLiteral("OUT"), 4, 0);
    return elements;
}

// "PIN<-source.output" for each input of box `id`, then "| reader<-" for every element reading it.
QString wiresOf(const std::vector<Element> &elements, quint64 id)
{
    QStringList parts;
    if (const auto *block = std::get_if<model::Block>(find(elements, id)))
        for (const model::BlockVariable &pin : block->inputVariables) {
            QString from;
            for (const model::Connection &c : pin.connectionPointIn->connections)
                from += QStringLiteral("%1.%2").arg(c.refLocalId).arg(c.formalParameter.value_or(QString()));
            parts << pin.formalParameter + QStringLiteral("<-") + from;
        }
    parts << QStringLiteral("|");
    for (const Element &e : elements)
        for (const model::ConnectionPointIn *input : model::inputPoints(e))
            for (const model::Connection &c : input->connections)
                if (c.refLocalId == id)
                    parts << QStringLiteral("%1<-%2").arg(model::header(e).localId).arg(c.formalParameter.value_or(QString()));
    return parts.join(QLatin1Char(' '));
}

} // namespace

class TestCfcStructure : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void storageOfBodies();
    void readsCodesysForm();
    void writesCodesysFormBack();
    void pinsAndRoutes_data();
    void pinsAndRoutes();
    void insertNumbersInOrder();
    void deleteClosesTheOrder();
    void connectReplacesTheInput();
    void replaceBlockKeepsTheWires_data();
    void replaceBlockKeepsTheWires();
    void takingEnEnoAwayDropsTheirWires();
    void orders_data();
    void orders();
    void moveAndSetInOrder_data();
    void moveAndSetInOrder();
};

void TestCfcStructure::storageOfBodies()
{
    model::Body codesys = model::Body::withLanguage(model::BodyLanguage::ST);
    codesys.addData.push_back({QStringLiteral("http://www.3s-software.com/plcopenxml/cfc"), QStringLiteral("implementation"), QStringLiteral("<CFC/>")});
    QCOMPARE(cfcStorageOf(codesys), std::optional(CfcStorage::Codesys));
    QCOMPARE(codesysCfcEntry(codesys), 0);
    model::Body withText = codesys;
    withText.setText(QStringLiteral("x := 1;"));
    QCOMPARE(cfcStorageOf(withText), std::nullopt); // ST that happens to carry the entry stays ST
    model::Body ours = model::Body::withLanguage(model::BodyLanguage::FBD);
    QCOMPARE(cfcStorageOf(ours), std::nullopt); // a plain FBD
    ours.addData.push_back({QString::fromLatin1(editors::kIecStudioCfcAddDataName), QStringLiteral("implementation"), QStringLiteral("<cfc/>")});
    QCOMPARE(cfcStorageOf(ours), std::optional(CfcStorage::Elements));
    QCOMPARE(editors::editorLanguage(ours), editors::EditorLanguage::CFC);
    QCOMPARE(editors::editorLanguage(codesys), editors::EditorLanguage::CFC);
}

void TestCfcStructure::readsCodesysForm()
{
    const CodesysCfcRead read = readCodesysCfc(QString::fromUtf8(kCodesysCounter));
    QCOMPARE(read.error, QString());
    // The anonymous connectors are gone; the wires go straight to their sources.
    QCOMPARE(read.elements.size(), std::size_t(3));
    QCOMPARE(connectionInto(read.elements, 1, 0).refLocalId, quint64(3));
    QCOMPARE(connectionInto(read.elements, 1, 0).formalParameter, std::nullopt); // a variable's only output
    QCOMPARE(connectionInto(read.elements, 6, 0).refLocalId, quint64(1));
    QCOMPARE(connectionInto(read.elements, 6, 0).formalParameter, std::optional(QStringLiteral("Out1")));
    QCOMPARE(connectionInto(read.elements, 1, 1).refLocalId, quint64(1)); // the loop: In2 reads Out1
    // Grid to drawing units: the input on row 14 feeds In1, the first pin under the title row 13.
    const model::ElementHeader &add = model::header(*find(read.elements, 1));
    QCOMPARE(add.position, (model::Position {360, 250}));
    QCOMPARE(model::header(*find(read.elements, 3)).position, (model::Position {180, 270}));
    QCOMPARE(cfcOutputPin(*find(read.elements, 3), std::nullopt), std::optional(QPointF(230, 280)));
    QCOMPARE(cfcInputPin(*find(read.elements, 1), 0), std::optional(QPointF(360, 280)));
    QCOMPARE(cfcInputPin(*find(read.elements, 6), 0)->y(), 280.0); // the output on the same row
    // The order counted from 1; the box's own addData kept.
    QCOMPARE(orderOf(read.elements), QStringLiteral("1:1 6:2"));
    QCOMPARE(add.addData.size(), std::size_t(1)); // CODESYS's call type, kept for the way back
    // Not XML: an error, no elements.
    const CodesysCfcRead broken = readCodesysCfc(QStringLiteral("<CFC><block"));
    QVERIFY(!broken.error.isEmpty());
    QVERIFY(broken.elements.empty());
}

void TestCfcStructure::writesCodesysFormBack()
{
    const CodesysCfcRead read = readCodesysCfc(QString::fromUtf8(kCodesysCounter));
    const QString written = writeCodesysCfc(read.elements);
    // One anonymous connector per output that has readers, after its source; grid positions; the
    // order from 0 again; relPositions on the pins.
    QVERIFY2(written.startsWith(QLatin1String("<CFC><inVariable localId=\"3\"")), qPrintable(written));
    QVERIFY(written.contains(QLatin1String("<position x=\"9\" y=\"14\"/>")));
    QCOMPARE(written.count(QLatin1String("<connector ")), 2);
    QVERIFY(written.contains(QLatin1String("<connector name=\"\" localId=\"7\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"3\" formalParameter=\"Step\"/>")));
    QVERIFY(written.contains(QLatin1String("executionOrderId=\"0\"")));
    QVERIFY(written.contains(QLatin1String("<position x=\"18\" y=\"13\"/>")));
    QVERIFY(written.contains(QLatin1String("<relPosition x=\"0\" y=\"1\"/>")));
    // Reading it again gives the same diagram.
    const CodesysCfcRead again = readCodesysCfc(written);
    QCOMPARE(again.error, QString());
    QVERIFY(again.elements == read.elements);
}

void TestCfcStructure::pinsAndRoutes_data()
{
    QTest::addColumn<double>("targetX");
    QTest::addColumn<double>("targetY");
    QTest::addColumn<bool>("broken");
    QTest::addColumn<int>("corners");
    // The source's output is at (100, 10); the target is a 40-wide output variable.
    QTest::newRow("in line: straight") << 200.0 << 0.0 << false << 2;
    QTest::newRow("lower: one step") << 200.0 << 60.0 << false << 4;
    QTest::newRow("too close: red") << 105.0 << 0.0 << true << 2;
    QTest::newRow("overlapping: red") << 90.0 << 0.0 << true << 2;
    QTest::newRow("behind, apart: around") << -100.0 << 100.0 << false << 6;
}

void TestCfcStructure::pinsAndRoutes()
{
    QFETCH(double, targetX);
    QFETCH(double, targetY);
    QFETCH(bool, broken);
    QFETCH(int, corners);
    std::vector<Element> elements {input(QStringLiteral("Go"), 60, 0), output(QStringLiteral("Lamp"), targetX, targetY)};
    model::header(elements[0]).localId = 1;
    model::header(elements[1]).localId = 2;
    const QPointF from = *cfcOutputPin(elements[0], std::nullopt);
    const QPointF to = *cfcInputPin(elements[1], 0);
    QCOMPARE(from, QPointF(100, 10));
    const CfcWire wire = routeCfcWire(from, to, cfcFrames(elements));
    QCOMPARE(wire.broken, broken);
    QCOMPARE(int(wire.points.size()), corners);
    QCOMPARE(wire.points.front(), from);
    QCOMPARE(wire.points.back(), to);
    for (qsizetype i = 1; i < wire.points.size() && !broken; ++i) // orthogonal
        QVERIFY(wire.points[i].x() == wire.points[i - 1].x() || wire.points[i].y() == wire.points[i - 1].y());
}

void TestCfcStructure::insertNumbersInOrder()
{
    std::vector<Element> elements = counterLoop();
    // Boxes and outputs run, in the order they were placed; the input does not.
    QCOMPARE(orderOf(elements), QStringLiteral("1:1 2:2 4:3"));
    QCOMPARE(model::header(*find(elements, 2)).position, (model::Position {340, 100}));
    const editors::EditOutcome o = insertElement(elements, input(QStringLiteral("x"), 0, 0), {33, 47});
    QCOMPARE(o.select, std::vector<quint64> {5});
    QCOMPARE(model::header(*find(elements, 5)).position, (model::Position {30, 50})); // snapped to 10
}

void TestCfcStructure::deleteClosesTheOrder()
{
    std::vector<Element> elements = counterLoop();
    QVERIFY(deleteElements(elements, {2}).ok());
    QCOMPARE(orderOf(elements), QStringLiteral("1:1 4:2"));
    // The wires from MOVE went with it.
    QVERIFY(model::inputPoints(*find(elements, 1))[0]->connections.empty());
    QVERIFY(model::inputPoints(*find(elements, 4))[0]->connections.empty());
    QVERIFY(!deleteElements(elements, {}).ok());
}

void TestCfcStructure::connectReplacesTheInput()
{
    std::vector<Element> elements = counterLoop();
    QVERIFY(connectPins(elements, 3, std::nullopt, 4, 0).ok());
    const auto &into = model::inputPoints(*find(elements, 4))[0]->connections;
    QCOMPARE(into.size(), std::size_t(1));
    QCOMPARE(into.front().refLocalId, quint64(3));
    // A one-output box's wire names its output, as CODESYS and Beremiz write it.
    QCOMPARE(connectionInto(elements, 2, 0).formalParameter, std::optional(QStringLiteral("OUT")));
    QVERIFY(!connectPins(elements, 3, std::nullopt, 4, 1).ok()); // no such input
    QVERIFY(!connectPins(elements, 9, std::nullopt, 4, 0).ok()); // no such element
}

void TestCfcStructure::replaceBlockKeepsTheWires_data()
{
    // In the counter loop ADD (1) reads MOVE (2) and the constant (3); MOVE and Count (4) read ADD.
    QTest::addColumn<quint64>("box");
    QTest::addColumn<QStringList>("inputs");
    QTest::addColumn<QStringList>("outputs");
    QTest::addColumn<QString>("expected");
    const QStringList in12 {QStringLiteral("IN1"), QStringLiteral("IN2")};
    const QStringList out {QStringLiteral("OUT")};
    QTest::newRow("ADD to MUL: by name") << quint64(1) << in12 << out << "IN1<-2.OUT IN2<-3. | 2<-OUT";
    QTest::newRow("EN/ENO added: EN unwired") << quint64(1) << QStringList {QStringLiteral("EN")} + in12
                                              << QStringList {QStringLiteral("ENO")} + out << "EN<- IN1<-2.OUT IN2<-3. | 2<-OUT";
    QTest::newRow("ADD to SEL: by name, then in turn") << quint64(1) << QStringList {QStringLiteral("G"), QStringLiteral("IN0"), QStringLiteral("IN1")}
                                          << out << "G<-3. IN0<- IN1<-2.OUT | 2<-OUT";
    QTest::newRow("MOVE to TON: OUT's readers lose it") << quint64(2) << QStringList {QStringLiteral("IN"), QStringLiteral("PT")}
                                                        << QStringList {QStringLiteral("Q"), QStringLiteral("ET")} << "IN<-1.OUT PT<- |";
}

void TestCfcStructure::replaceBlockKeepsTheWires()
{
    QFETCH(quint64, box);
    QFETCH(QStringList, inputs);
    QFETCH(QStringList, outputs);
    QFETCH(QString, expected);
    std::vector<Element> elements = counterLoop();
    const model::ElementHeader before = model::header(*find(elements, box));
    QVERIFY(replaceBlock(elements, box, ::box(QStringLiteral("NEW"), inputs, outputs, 0, 0)).ok());
    QCOMPARE(wiresOf(elements, box), expected);
    // Where it stands and when it runs stay.
    QCOMPARE(model::header(*find(elements, box)).position, before.position);
    QCOMPARE(model::header(*find(elements, box)).executionOrderId, before.executionOrderId);
    QCOMPARE(std::get<model::Block>(*find(elements, box)).typeName, QStringLiteral("NEW"));
    QVERIFY(!replaceBlock(elements, 4, ::box(QStringLiteral("NEW"), inputs, outputs, 0, 0)).ok()); // Count is no box
}

void TestCfcStructure::takingEnEnoAwayDropsTheirWires()
{
    // ADD with EN/ENO: EN reads the constant, Count reads ENO. Without them ENO's reader is unwired.
    std::vector<Element> elements = counterLoop();
    const QStringList in12 {QStringLiteral("IN1"), QStringLiteral("IN2")};
    QVERIFY(replaceBlock(elements, 1, box(QStringLiteral("ADD"), QStringList {QStringLiteral("EN")} + in12,
                                          {QStringLiteral("ENO"), QStringLiteral("OUT")}, 0, 0)).ok());
    QVERIFY(connectPins(elements, 3, std::nullopt, 1, 0).ok());
    QVERIFY(connectPins(elements, 1, QStringLiteral("ENO"), 4, 0).ok());
    QCOMPARE(wiresOf(elements, 1), QStringLiteral("EN<-3. IN1<-2.OUT IN2<-3. | 2<-OUT 4<-ENO"));
    QVERIFY(replaceBlock(elements, 1, box(QStringLiteral("ADD"), in12, {QStringLiteral("OUT")}, 0, 0)).ok());
    QCOMPARE(wiresOf(elements, 1), QStringLiteral("IN1<-2.OUT IN2<-3. | 2<-OUT"));
}

void TestCfcStructure::orders_data()
{
    QTest::addColumn<QString>("how");
    QTest::addColumn<QString>("expected");
    // MOVE is placed first: by data flow the loop is entered at its topmost, leftmost element
    // (ADD, which then reads MOVE of the scan before), MOVE follows, then what reads MOVE, top
    // to bottom. Topology: top to bottom, left to right.
    QTest::newRow("data flow") << "flow" << "1:2 2:1 4:4 5:3";
    QTest::newRow("topology") << "topology" << "1:3 2:2 4:4 5:1";
}

void TestCfcStructure::orders()
{
    QFETCH(QString, how);
    QFETCH(QString, expected);
    std::vector<Element> elements;
    insertElement(elements, box(QStringLiteral("MOVE"), {QStringLiteral("IN")}, {QStringLiteral("OUT")}, 0, 0), {340, 100});
    insertElement(elements, box(QStringLiteral("ADD"), {QStringLiteral("IN1"), QStringLiteral("IN2")}, {QStringLiteral("OUT")}, 0, 0), {200, 100});
    insertElement(elements, input(QStringLiteral("1"), 0, 0), {100, 140});
    insertElement(elements, output(QStringLiteral("Count"), 0, 0), {480, 120});
    insertElement(elements, output(QStringLiteral("Copy"), 0, 0), {480, 60});
    connectPins(elements, 1, QStringLiteral("OUT"), 2, 0);
    connectPins(elements, 3, std::nullopt, 2, 1);
    connectPins(elements, 2, QStringLiteral("OUT"), 1, 0);
    connectPins(elements, 1, QStringLiteral("OUT"), 4, 0);
    connectPins(elements, 1, QStringLiteral("OUT"), 5, 0);
    QVERIFY((how == QLatin1String("flow") ? orderByDataFlow(elements) : orderByTopology(elements)).ok());
    QCOMPARE(orderOf(elements), expected);
}

void TestCfcStructure::moveAndSetInOrder_data()
{
    QTest::addColumn<int>("move");
    QTest::addColumn<QString>("expected");
    QTest::newRow("Count earlier") << int(OrderMove::Earlier) << "1:1 2:3 4:2";
    QTest::newRow("Count later: already last") << int(OrderMove::Later) << "1:1 2:2 4:3";
    QTest::newRow("Count to the front") << int(OrderMove::ToFront) << "1:2 2:3 4:1";
    QTest::newRow("Count to the back") << int(OrderMove::ToBack) << "1:1 2:2 4:3";
}

void TestCfcStructure::moveAndSetInOrder()
{
    QFETCH(int, move);
    QFETCH(QString, expected);
    std::vector<Element> elements = counterLoop();
    QVERIFY(moveInOrder(elements, {4}, OrderMove(move)).ok());
    QCOMPARE(orderOf(elements), expected);
    // Setting a number shifts the others.
    std::vector<Element> numbered = counterLoop();
    QVERIFY(setOrderNumber(numbered, 1, 3).ok());
    QCOMPARE(orderOf(numbered), QStringLiteral("1:3 2:1 4:2"));
    QVERIFY(!setOrderNumber(numbered, 1, 4).ok());
    QVERIFY(!setOrderNumber(numbered, 3, 1).ok()); // an input has no number
    QVERIFY(!moveInOrder(numbered, {3}, OrderMove::Earlier).ok());
}

QTEST_GUILESS_MAIN(TestCfcStructure)
#include "tst_cfcstructure.moc"
