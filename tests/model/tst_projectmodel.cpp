#include "model/projectmodel.h"
#include "model/undo/bodyelementscommand.h"
#include "model/undo/poucommands.h"
#include "modelfixture.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace iec::model;
using namespace iec::test;

class TestProjectModel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void addPouAssignsFreshIdsAndSignals();
    void renameChangesNameAndKeepsId_data();
    void renameChangesNameAndKeepsId();
    void removeUnknownPouChangesNothing();
    void resetKeepsGivenIdsAndNumbersTheRest();
    void duplicateMakesAnOrdinaryCopyAfterTheOriginal();
    void actionsAndTransitions();
    void dataTypes();
    void variables();
    void insertElementFindsAFreeLocalId_data();
    void insertElementFindsAFreeLocalId();
    void removeElementDropsItsWires();
    void moveToTheSamePlaceChangesNothing();
    void connectAndDisconnect();
    void bodyText();
    void replaceElementsSignalsOnceAndKeepsOrder_data();
    void replaceElementsSignalsOnceAndKeepsOrder();
    void replaceElementsCommandUndoesExactly();
    void addPouCommandRedoUndoRedo();
    void renameCommandsMergeIntoOneStep();
};

void TestProjectModel::addPouAssignsFreshIdsAndSignals()
{
    ProjectModel model;
    QSignalSpy added(&model, &ProjectModel::pouAdded);
    const quint64 revision = model.revision();

    const PouId first = model.addPou({.name = QStringLiteral("Main")});
    const PouId second = model.addPou({.name = QStringLiteral("Conveyor"), .kind = PouKind::FunctionBlock});

    QVERIFY(first.isValid());
    QVERIFY(second.isValid());
    QVERIFY(first != second);
    QCOMPARE(added.count(), 2);
    QCOMPARE(added.at(1).at(0).value<PouId>(), second);
    QCOMPARE(model.revision(), revision + 2);
    QCOMPARE(model.project().findPou(QStringLiteral("conveyor"))->id, second);
}

void TestProjectModel::renameChangesNameAndKeepsId_data()
{
    QTest::addColumn<QString>("newName");
    QTest::addColumn<bool>("changed");
    QTest::newRow("new name") << QStringLiteral("Pump") << true;
    QTest::newRow("same name") << QStringLiteral("Main") << false;
    QTest::newRow("other case") << QStringLiteral("MAIN") << true;
}

void TestProjectModel::renameChangesNameAndKeepsId()
{
    QFETCH(QString, newName);
    QFETCH(bool, changed);
    ProjectModel model;
    const PouId id = model.addPou({.name = QStringLiteral("Main")});
    QSignalSpy renamed(&model, &ProjectModel::pouRenamed);
    const quint64 revision = model.revision();

    QCOMPARE(model.renamePou(id, newName), changed);

    QCOMPARE(model.project().findPou(id)->name, newName);
    QCOMPARE(renamed.count(), changed ? 1 : 0);
    QCOMPARE(model.revision(), revision + (changed ? 1 : 0));
}

void TestProjectModel::removeUnknownPouChangesNothing()
{
    ProjectModel model;
    model.addPou({.name = QStringLiteral("Main")});
    QSignalSpy removed(&model, &ProjectModel::pouRemoved);
    const quint64 revision = model.revision();

    QVERIFY(!model.removePou(PouId {999}));
    QCOMPARE(removed.count(), 0);
    QCOMPARE(model.revision(), revision);
    QCOMPARE(model.project().types.pous.size(), std::size_t {1});
}

void TestProjectModel::resetKeepsGivenIdsAndNumbersTheRest()
{
    ProjectModel model;
    QSignalSpy reset(&model, &ProjectModel::projectReset);
    Project project;
    project.types.pous.push_back({.id = PouId {7}, .name = QStringLiteral("A")});
    project.types.pous.push_back({.name = QStringLiteral("B")});

    model.reset(project);

    QCOMPARE(reset.count(), 1);
    QCOMPARE(model.project().types.pous.at(0).id, PouId {7});
    QCOMPARE(model.project().types.pous.at(1).id, PouId {8});
    QCOMPARE(model.addPou({.name = QStringLiteral("C")}), PouId {9});
}

void TestProjectModel::duplicateMakesAnOrdinaryCopyAfterTheOriginal()
{
    ProjectModel model;
    model.reset(everyElementProject());
    const PouId motor = pouId(model, "Motor");
    QSignalSpy added(&model, &ProjectModel::pouAdded);

    const PouId copy = model.duplicatePou(motor, QStringLiteral("Motor2"));

    QVERIFY(copy.isValid() && copy != motor);
    QCOMPARE(added.count(), 1);
    QCOMPARE(model.pouIndex(copy), model.pouIndex(motor) + 1);
    const Pou &duplicate = *model.project().findPou(copy);
    QCOMPARE(duplicate.name, QStringLiteral("Motor2"));
    QCOMPARE(duplicate.addDataSlot, quint32(0));
    QCOMPARE(duplicate.actions, model.project().findPou(motor)->actions);
    QVERIFY(!model.duplicatePou(PouId {999}, QStringLiteral("X")).isValid());
}

void TestProjectModel::actionsAndTransitions()
{
    ProjectModel model;
    model.reset(everyElementProject());
    const PouId motor = pouId(model, "Motor");
    QSignalSpy changed(&model, &ProjectModel::pouPartsChanged);
    const auto action = BodyRef::Part::Action;
    const auto transition = BodyRef::Part::Transition;

    QVERIFY(model.addPouPart(
        motor, action, {.name = QStringLiteral("Start"), .body = Body::withLanguage(BodyLanguage::LD)}, 0));
    QVERIFY(!model.addPouPart(motor, action, {.name = QStringLiteral("reset")})); // names are case-insensitive
    QCOMPARE(model.pouPartIndex(motor, action, QStringLiteral("Reset")), 1);
    QVERIFY(model.renamePouPart(motor, transition, QStringLiteral("Done"), QStringLiteral("Finished")));
    QCOMPARE(model.body({motor, transition, QStringLiteral("Finished")})->language(), BodyLanguage::IL);
    QVERIFY(model.removePouPart(motor, action, QStringLiteral("Start")));
    QVERIFY(!model.removePouPart(motor, action, QStringLiteral("Start")));
    QCOMPARE(changed.count(), 3);
    QCOMPARE(changed.at(0).at(0).value<PouId>(), motor);
}

void TestProjectModel::dataTypes()
{
    ProjectModel model;
    model.reset(everyElementProject());
    QSignalSpy changed(&model, &ProjectModel::dataTypesChanged);

    QVERIFY(model.addDataType({.name = QStringLiteral("Level")}, 0));
    QVERIFY(!model.addDataType({.name = QStringLiteral("LEVEL")}));
    QCOMPARE(model.dataTypeIndex(QStringLiteral("Level")), 0);
    QVERIFY(model.renameDataType(QStringLiteral("Level"), QStringLiteral("Height")));
    DataTypeDecl height = *model.project().findDataType(QStringLiteral("Height"));
    height.baseType.kind = StringType {.wide = true, .length = QStringLiteral("8")};
    QVERIFY(model.changeDataType(QStringLiteral("Height"), height));
    QVERIFY(!model.changeDataType(QStringLiteral("Height"), height));
    QVERIFY(model.removeDataType(QStringLiteral("Height")));
    QCOMPARE(changed.count(), 4);
}

void TestProjectModel::variables()
{
    ProjectModel model;
    model.reset(everyElementProject());
    const PouId chart = pouId(model, "Chart"); // no interface at all
    QSignalSpy changed(&model, &ProjectModel::variablesChanged);

    QVERIFY(model.addVariable(chart, VarListKind::Input, {.name = QStringLiteral("Go")}));
    QVERIFY(model.addVariable(chart, VarListKind::Input, {.name = QStringLiteral("Stop")}, 0));
    QVERIFY(!model.addVariable(chart, VarListKind::Local, {.name = QStringLiteral("go")}));
    const Interface &declarations = *model.project().findPou(chart)->pouInterface;
    QCOMPARE(declarations.varLists.size(), std::size_t {1});
    QCOMPARE(declarations.varLists.front().variables.front().name, QStringLiteral("Stop"));
    Variable go = *model.findVariable(chart, QStringLiteral("Go"));
    go.address = QStringLiteral("%IX0.1");
    QVERIFY(model.changeVariable(chart, QStringLiteral("Go"), go));
    QVERIFY(model.removeVariable(chart, QStringLiteral("Stop")));
    QVERIFY(!model.removeVariable(chart, QStringLiteral("Stop")));
    QVERIFY(model.setInterface(chart, std::nullopt));
    QCOMPARE(changed.count(), 5);
    QCOMPARE(changed.at(4).at(0).value<PouId>(), chart);
}

void TestProjectModel::insertElementFindsAFreeLocalId_data()
{
    QTest::addColumn<quint64>("requested");
    QTest::addColumn<quint64>("given");
    QTest::newRow("free") << quint64(500) << quint64(500);
    QTest::newRow("zero") << quint64(0) << quint64(12);
    QTest::newRow("taken") << quint64(3) << quint64(12);
}

void TestProjectModel::insertElementFindsAFreeLocalId()
{
    QFETCH(quint64, requested);
    QFETCH(quint64, given);
    ProjectModel model;
    model.reset(everyElementProject());
    const BodyRef ladder = bodyOf(model, "Ladder"); // localIds 1..11
    QSignalSpy inserted(&model, &ProjectModel::elementsInserted);
    Contact contact;
    contact.localId = requested;
    contact.variable = QStringLiteral("E");

    QCOMPARE(model.insertElement(ladder, contact, 1), given);

    QCOMPARE(inserted.count(), 1);
    QCOMPARE(inserted.at(0).at(0).value<BodyRef>(), ladder);
    QCOMPARE(inserted.at(0).at(1).value<QList<quint64>>(), QList<quint64> {given});
    QCOMPARE(model.elementIndex(ladder, given), 1);
    QCOMPARE(model.insertElement(bodyOf(model, "Scale"), contact), quint64(0)); // an ST body
}

void TestProjectModel::removeElementDropsItsWires()
{
    ProjectModel model;
    model.reset(everyElementProject());
    const BodyRef blocks = bodyOf(model, "Blocks");
    QSignalSpy removed(&model, &ProjectModel::elementsRemoved);
    QSignalSpy rewired(&model, &ProjectModel::connectionsChanged);

    QVERIFY(model.removeElement(blocks, 2)); // the TON block feeds outVariable 3 and inOutVariable 4

    QCOMPARE(removed.count(), 1);
    QCOMPARE(rewired.count(), 2);
    QCOMPARE(rewired.at(0).at(1).toULongLong(), quint64(3));
    QCOMPARE(rewired.at(1).at(1).toULongLong(), quint64(4));
    QVERIFY(std::get<OutVariable>(*model.element(blocks, 3)).connectionPointIn->connections.empty());
    QVERIFY(!model.element(blocks, 2));
    QVERIFY(!model.removeElement(blocks, 2));
}

void TestProjectModel::moveToTheSamePlaceChangesNothing()
{
    ProjectModel model;
    model.reset(everyElementProject());
    const BodyRef ladder = bodyOf(model, "Ladder");
    QSignalSpy changed(&model, &ProjectModel::elementsChanged);
    const quint64 revision = model.revision();

    QVERIFY(!model.moveElement(ladder, 2, {50, 22.5}));
    QCOMPARE(model.revision(), revision);
    QVERIFY(model.moveElement(ladder, 2, {60, 22.5}));
    QCOMPARE(model.revision(), revision + 1);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(header(*model.element(ladder, 2)).position, (Position {60, 22.5}));
}

void TestProjectModel::connectAndDisconnect()
{
    ProjectModel model;
    model.reset(everyElementProject());
    const BodyRef ladder = bodyOf(model, "Ladder");
    QSignalSpy changed(&model, &ProjectModel::connectionsChanged);

    QVERIFY(!model.connect(ladder, 6, 1, {.refLocalId = 5})); // a coil has one input pin
    QVERIFY(!model.connect(ladder, 6, 0, {.refLocalId = 99})); // no such source
    QVERIFY(model.connect(ladder, 6, 0, {.refLocalId = 5}));
    QCOMPARE(std::get<Coil>(*model.element(ladder, 6)).connectionPointIn->connections.size(), std::size_t {2});
    QVERIFY(model.disconnect(ladder, 6, 0, 4));
    QVERIFY(!model.disconnect(ladder, 6, 0, 4));
    QCOMPARE(std::get<Coil>(*model.element(ladder, 6)).connectionPointIn->connections.front().refLocalId, quint64(5));
    QCOMPARE(changed.count(), 2);
    QCOMPARE(changed.at(0).at(1).toULongLong(), quint64(6));
}

void TestProjectModel::bodyText()
{
    ProjectModel model;
    model.reset(everyElementProject());
    QSignalSpy changed(&model, &ProjectModel::bodyTextChanged);
    const BodyRef reset {pouId(model, "Motor"), BodyRef::Part::Action, QStringLiteral("Reset")};

    QVERIFY(model.setBodyText(reset, QStringLiteral("Count := 1;")));
    QVERIFY(!model.setBodyText(reset, QStringLiteral("Count := 1;")));
    QVERIFY(!model.setBodyText(bodyOf(model, "Ladder"), QStringLiteral("x")));
    QCOMPARE(model.body(reset)->text(), QStringLiteral("Count := 1;"));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.at(0).at(0).value<BodyRef>(), reset);
}

namespace {

// A body of comments "1".."5" (localId = text). A target is written as localIds in order; a
// trailing ' changes that comment's text: "1 2 3' 6 5" keeps 1 and 2, changes 3, removes 4,
// inserts 6 and keeps 5.
Element numberedComment(quint64 localId, bool changed = false)
{
    Comment comment;
    comment.localId = localId;
    comment.content.text = QString::number(localId) + (changed ? QStringLiteral("'") : QString());
    return comment;
}

std::vector<Element> commentsFrom(const QString &spec)
{
    std::vector<Element> elements;
    for (const QString &word : spec.split(QLatin1Char(' '), Qt::SkipEmptyParts))
        elements.push_back(numberedComment(word.chopped(word.endsWith(QLatin1Char('\'')) ? 1 : 0).toULongLong(),
            word.endsWith(QLatin1Char('\''))));
    return elements;
}

QString idsOf(const QSignalSpy &spy)
{
    if (spy.isEmpty())
        return QStringLiteral("-");
    QStringList ids;
    for (quint64 id : spy.front().at(1).value<QList<quint64>>())
        ids << QString::number(id);
    return ids.join(QLatin1Char(' ')) + (spy.count() > 1 ? QStringLiteral(" (%1 signals)").arg(spy.count()) : QString());
}

BodyRef commentBody(ProjectModel &model)
{
    Pou pou {.name = QStringLiteral("Chart")};
    pou.bodies.push_back(Body::withLanguage(BodyLanguage::FBD));
    *pou.bodies.front().elements() = commentsFrom(QStringLiteral("1 2 3 4 5"));
    Project project;
    project.types.pous.push_back(pou);
    model.reset(project);
    return {model.project().types.pous.front().id, BodyRef::Part::Pou, {}};
}

} // namespace

void TestProjectModel::replaceElementsSignalsOnceAndKeepsOrder_data()
{
    QTest::addColumn<QString>("target");
    QTest::addColumn<QString>("removed");
    QTest::addColumn<QString>("inserted");
    QTest::addColumn<QString>("changed");
    QTest::newRow("nothing") << "1 2 3 4 5" << "-" << "-" << "-";
    QTest::newRow("one changed") << "1 2 3' 4 5" << "-" << "-" << "3";
    QTest::newRow("mixed") << "1 2 3' 6 5" << "4" << "6" << "3";
    QTest::newRow("all removed") << "" << "1 2 3 4 5" << "-" << "-";
    QTest::newRow("inserted in the middle") << "1 7 2 3 8 4 5" << "-" << "7 8" << "-";
    QTest::newRow("moved to the front") << "5 1 2 3 4" << "-" << "-" << "5 1 2 3 4";
    QTest::newRow("two swapped") << "1 2 4 3 5" << "-" << "-" << "4 3";
    QTest::newRow("swapped and changed") << "1 2 4' 3 5" << "-" << "-" << "4 3";
    QTest::newRow("localId 0") << "0 1 2 3 4 5" << "-" << "0" << "-";
    // The unchanged head and tail are compared in place, the window between them by id.
    QTest::newRow("changed at both ends, inserted between") << "1' 2 7 3 4 5'" << "-" << "7" << "1 5";
    QTest::newRow("removed at the end") << "1 2 3" << "4 5" << "-" << "-";
    QTest::newRow("removed at the front") << "3 4 5" << "1 2" << "-" << "-";
    QTest::newRow("removed between changed ends") << "1' 2 4 5'" << "3" << "-" << "1 5";
    QTest::newRow("appended") << "1 2 3 4 5 6" << "-" << "6" << "-";
    QTest::newRow("reversed") << "5 4 3 2 1" << "-" << "-" << "5 4 2 1";
}

void TestProjectModel::replaceElementsSignalsOnceAndKeepsOrder()
{
    QFETCH(QString, target);
    QFETCH(QString, removed);
    QFETCH(QString, inserted);
    QFETCH(QString, changed);
    ProjectModel model;
    const BodyRef ref = commentBody(model);
    QSignalSpy removedSpy(&model, &ProjectModel::elementsRemoved);
    QSignalSpy insertedSpy(&model, &ProjectModel::elementsInserted);
    QSignalSpy changedSpy(&model, &ProjectModel::elementsChanged);
    QSignalSpy connectionsSpy(&model, &ProjectModel::connectionsChanged);
    const quint64 revision = model.revision();
    QStringList order;
    QObject::connect(&model, &ProjectModel::elementsRemoved, &model, [&] { order << QStringLiteral("removed"); });
    QObject::connect(&model, &ProjectModel::elementsInserted, &model, [&] { order << QStringLiteral("inserted"); });
    QObject::connect(&model, &ProjectModel::elementsChanged, &model, [&] { order << QStringLiteral("changed"); });

    const bool expectChange = removed != QLatin1String("-") || inserted != QLatin1String("-") || changed != QLatin1String("-");
    QCOMPARE(model.replaceElements(ref, commentsFrom(target)), expectChange);

    QVERIFY(*model.body(ref)->elements() == commentsFrom(target));
    QCOMPARE(idsOf(removedSpy), removed);
    QCOMPARE(idsOf(insertedSpy), inserted);
    QCOMPARE(idsOf(changedSpy), changed);
    QCOMPARE(connectionsSpy.count(), 0);
    QCOMPARE(model.revision(), revision + (expectChange ? 1 : 0));
    QStringList expectedOrder;
    if (removed != QLatin1String("-"))
        expectedOrder << QStringLiteral("removed");
    if (inserted != QLatin1String("-"))
        expectedOrder << QStringLiteral("inserted");
    if (changed != QLatin1String("-"))
        expectedOrder << QStringLiteral("changed");
    QCOMPARE(order, expectedOrder);
    for (const QSignalSpy *spy : {&removedSpy, &insertedSpy, &changedSpy}) {
        if (!spy->isEmpty())
            QCOMPARE(spy->front().at(0).value<BodyRef>(), ref);
    }
}

void TestProjectModel::replaceElementsCommandUndoesExactly()
{
    ProjectModel model;
    const BodyRef ref = commentBody(model);
    // Two elements with one localId are refused: the body stays as it was.
    QVERIFY(!model.replaceElements(ref, commentsFrom(QStringLiteral("1 1"))));
    QVERIFY(!model.replaceElements(ref, commentsFrom(QStringLiteral("1 2 3 4 5 1")))); // the same id at both ends
    QVERIFY(!model.replaceElements({}, commentsFrom(QStringLiteral("1"))));
    const std::vector<Element> before = *model.body(ref)->elements();
    QVERIFY(before == commentsFrom(QStringLiteral("1 2 3 4 5")));
    QUndoStack stack;
    // An edit that changes nothing leaves no step to undo.
    stack.push(new SetBodyElementsCommand(model, ref, before, QStringLiteral("nothing")));
    QCOMPARE(stack.count(), 0);
    stack.push(new SetBodyElementsCommand(model, ref, commentsFrom(QStringLiteral("2 2")), QStringLiteral("refused")));
    QCOMPARE(stack.count(), 0);
    QVERIFY(*model.body(ref)->elements() == before);
    stack.push(new SetBodyElementsCommand(model, ref, commentsFrom(QStringLiteral("6 2' 1 5")), QStringLiteral("edit")));
    QVERIFY(*model.body(ref)->elements() == commentsFrom(QStringLiteral("6 2' 1 5")));
    QCOMPARE(stack.undoText(), QStringLiteral("edit"));
    stack.undo();
    QVERIFY(*model.body(ref)->elements() == before);
    stack.redo();
    QVERIFY(*model.body(ref)->elements() == commentsFrom(QStringLiteral("6 2' 1 5")));
}

void TestProjectModel::addPouCommandRedoUndoRedo()
{
    ProjectModel model;
    QUndoStack stack;
    const Project before = model.project();

    Pou pou {.name = QStringLiteral("Main")};
    pou.bodies.push_back(Body::withLanguage(BodyLanguage::SFC));
    stack.push(new AddPouCommand(model, pou));
    const Project after = model.project();
    QCOMPARE(after.types.pous.size(), std::size_t {1});
    QCOMPARE(after.types.pous.front().language(), BodyLanguage::SFC);

    stack.undo();
    QVERIFY(model.project() == before);
    stack.redo();
    QVERIFY(model.project() == after); // same id again, so later commands that hold it stay valid
}

void TestProjectModel::renameCommandsMergeIntoOneStep()
{
    ProjectModel model;
    const PouId id = model.addPou({.name = QStringLiteral("Main")});
    QUndoStack stack;

    stack.push(new RenamePouCommand(model, id, QStringLiteral("Ma")));
    stack.push(new RenamePouCommand(model, id, QStringLiteral("Mixer")));

    QCOMPARE(stack.count(), 1);
    QCOMPARE(model.project().findPou(id)->name, QStringLiteral("Mixer"));
    stack.undo();
    QCOMPARE(model.project().findPou(id)->name, QStringLiteral("Main"));
    stack.redo();
    QCOMPARE(model.project().findPou(id)->name, QStringLiteral("Mixer"));
}

QTEST_GUILESS_MAIN(TestProjectModel)
#include "tst_projectmodel.moc"
