#include "model/projectmodel.h"
#include "model/undo/poucommands.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace iec::model;

class TestProjectModel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void addPouAssignsFreshIdsAndSignals();
    void renameChangesNameAndKeepsId_data();
    void renameChangesNameAndKeepsId();
    void removeUnknownPouChangesNothing();
    void resetKeepsGivenIdsAndNumbersTheRest();
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

    QVERIFY(!model.removePou(PouId{999}));
    QCOMPARE(removed.count(), 0);
    QCOMPARE(model.revision(), revision);
    QCOMPARE(model.project().pous.size(), std::size_t{1});
}

void TestProjectModel::resetKeepsGivenIdsAndNumbersTheRest()
{
    ProjectModel model;
    QSignalSpy reset(&model, &ProjectModel::projectReset);
    Project project;
    project.pous.push_back({.id = PouId{7}, .name = QStringLiteral("A")});
    project.pous.push_back({.name = QStringLiteral("B")});

    model.reset(project);

    QCOMPARE(reset.count(), 1);
    QCOMPARE(model.project().pous.at(0).id, PouId{7});
    QCOMPARE(model.project().pous.at(1).id, PouId{8});
    QCOMPARE(model.addPou({.name = QStringLiteral("C")}), PouId{9});
}

void TestProjectModel::addPouCommandRedoUndoRedo()
{
    ProjectModel model;
    QUndoStack stack;
    const Project before = model.project();

    stack.push(new AddPouCommand(model, {.name = QStringLiteral("Main"), .language = BodyLanguage::SFC}));
    const Project after = model.project();
    QCOMPARE(after.pous.size(), std::size_t{1});
    QCOMPARE(after.pous.front().language, BodyLanguage::SFC);

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
