#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "model/projectmodel.h"

#include <QSignalSpy>
#include <QTest>

using namespace iec::app;
using namespace iec::model;

class TestProjectTree : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void groupsPousByKindWithTheirParts();
    void displayTextsAndBodyRefs_data();
    void displayTextsAndBodyRefs();
    void showsDataTypesAndInstances();
    void viewKeepsExpansionAndCurrentNodeAcrossRebuilds();
    void activatingAnActionAsksToOpenItsBody();
};

namespace {

Pou pou(const QString &name, PouKind kind, BodyLanguage language)
{
    Pou value;
    value.name = name;
    value.kind = kind;
    value.bodies.push_back(Body::withLanguage(language));
    return value;
}

PouPart part(const QString &name, BodyLanguage language)
{
    PouPart value;
    value.name = name;
    value.body = Body::withLanguage(language);
    return value;
}

Project sampleProject()
{
    Project project;
    Pou mixer = pou(QStringLiteral("Mixer"), PouKind::Program, BodyLanguage::SFC);
    mixer.actions.push_back(part(QStringLiteral("Fill"), BodyLanguage::ST));
    mixer.actions.push_back(part(QStringLiteral("Drain"), BodyLanguage::LD));
    mixer.transitions.push_back(part(QStringLiteral("Full"), BodyLanguage::IL));
    project.types.pous.push_back(mixer);
    project.types.pous.push_back(pou(QStringLiteral("Valve"), PouKind::FunctionBlock, BodyLanguage::FBD));
    project.types.pous.push_back(pou(QStringLiteral("Scale"), PouKind::Function, BodyLanguage::ST));
    project.types.pous.push_back(pou(QStringLiteral("Main"), PouKind::Program, BodyLanguage::LD));
    DataTypeDecl type;
    type.name = QStringLiteral("Recipe");
    project.types.dataTypes.push_back(type);
    Configuration configuration;
    configuration.name = QStringLiteral("Config");
    Resource resource;
    resource.name = QStringLiteral("CPU");
    Task task;
    task.name = QStringLiteral("MainTask");
    resource.tasks.push_back(task);
    VarList globals;
    globals.kind = VarListKind::Global;
    globals.name = QStringLiteral("IO");
    resource.globalVars.push_back(globals);
    configuration.resources.push_back(resource);
    project.instances.configurations.push_back(configuration);
    return project;
}

QStringList childTexts(const QAbstractItemModel &model, const QModelIndex &parent)
{
    QStringList texts;
    for (int row = 0; row < model.rowCount(parent); ++row)
        texts << model.index(row, 0, parent).data().toString();
    return texts;
}

} // namespace

void TestProjectTree::groupsPousByKindWithTheirParts()
{
    ProjectModel projectModel;
    projectModel.reset(sampleProject());
    ProjectTreeModel tree(projectModel);

    QCOMPARE(childTexts(tree, {}),
             (QStringList{QStringLiteral("Programs"), QStringLiteral("Function Blocks"), QStringLiteral("Functions"),
                          QStringLiteral("Data Types"), QStringLiteral("Global Variables"),
                          QStringLiteral("Configurations")}));
    const QModelIndex programs = tree.index(0, 0);
    QCOMPARE(childTexts(tree, programs), (QStringList{QStringLiteral("Mixer (PRG)"), QStringLiteral("Main (PRG)")}));
    QCOMPARE(childTexts(tree, tree.index(0, 0, programs)),
             (QStringList{QStringLiteral("Fill"), QStringLiteral("Drain"), QStringLiteral("Full")}));
    QCOMPARE(childTexts(tree, tree.index(1, 0)), QStringList{QStringLiteral("Valve (FB)")});
    QCOMPARE(childTexts(tree, tree.index(2, 0)), QStringList{QStringLiteral("Scale (FUN)")});
    QVERIFY(!tree.index(0, 0, programs).data(Qt::DecorationRole).value<QIcon>().isNull());
}

void TestProjectTree::displayTextsAndBodyRefs_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("part");
    QTest::addColumn<QString>("partName");
    QTest::addColumn<QString>("tooltip");
    QTest::newRow("pou") << ProjectTreeModel::pouKey(PouId{1}) << int(BodyRef::Part::Pou) << QString()
                         << QStringLiteral("Mixer, written in Sequential Function Chart (SFC)");
    QTest::newRow("action") << QStringLiteral("a:1:drain") << int(BodyRef::Part::Action) << QStringLiteral("Drain")
                            << QStringLiteral("Drain, written in Ladder Diagram (LD)");
    QTest::newRow("transition") << QStringLiteral("t:1:full") << int(BodyRef::Part::Transition)
                                << QStringLiteral("Full") << QStringLiteral("Full, written in Instruction List (IL)");
}

void TestProjectTree::displayTextsAndBodyRefs()
{
    QFETCH(QString, key);
    QFETCH(int, part);
    QFETCH(QString, partName);
    QFETCH(QString, tooltip);
    ProjectModel projectModel;
    projectModel.reset(sampleProject());
    ProjectTreeModel tree(projectModel);

    const QModelIndex index = tree.indexForKey(key);
    QVERIFY(index.isValid());
    QCOMPARE(tree.key(index), key);
    const BodyRef expected{PouId{1}, BodyRef::Part(part), partName};
    QCOMPARE(tree.bodyRef(index), std::optional(expected));
    QCOMPARE(index.data(Qt::ToolTipRole).toString(), tooltip);
}

void TestProjectTree::showsDataTypesAndInstances()
{
    ProjectModel projectModel;
    projectModel.reset(sampleProject());
    ProjectTreeModel tree(projectModel);

    QCOMPARE(childTexts(tree, tree.index(3, 0)), QStringList{QStringLiteral("Recipe")});
    QCOMPARE(childTexts(tree, tree.index(4, 0)), QStringList{QStringLiteral("IO")});
    const QModelIndex configuration = tree.index(0, 0, tree.index(5, 0));
    QCOMPARE(configuration.data().toString(), QStringLiteral("Config"));
    const QModelIndex resource = tree.index(0, 0, configuration);
    QCOMPARE(resource.data().toString(), QStringLiteral("CPU"));
    QCOMPARE(childTexts(tree, resource), QStringList{QStringLiteral("MainTask")});
    QCOMPARE(tree.bodyRef(resource), std::nullopt);
}

void TestProjectTree::viewKeepsExpansionAndCurrentNodeAcrossRebuilds()
{
    ProjectModel projectModel;
    projectModel.reset(sampleProject());
    ProjectTreeModel tree(projectModel);
    ProjectTreeView view;
    view.setProjectModel(&tree);
    view.selectKey(QStringLiteral("t:1:full")); // expands Programs and Mixer
    QVERIFY(view.isExpanded(tree.indexForKey(ProjectTreeModel::pouKey(PouId{1}))));
    view.collapse(tree.indexForKey(ProjectTreeModel::folderKey(ProjectTreeModel::Folder::Functions)));

    QSignalSpy reset(&tree, &QAbstractItemModel::modelReset);
    const PouId added = projectModel.addPou(pou(QStringLiteral("Alarm"), PouKind::Program, BodyLanguage::ST));
    projectModel.renamePou(PouId{4}, QStringLiteral("PLC_PRG"));

    QCOMPARE(reset.count(), 2);
    QCOMPARE(view.currentKey(), QStringLiteral("t:1:full"));
    QVERIFY(view.isExpanded(tree.indexForKey(ProjectTreeModel::pouKey(PouId{1}))));
    QVERIFY(!view.isExpanded(tree.indexForKey(ProjectTreeModel::folderKey(ProjectTreeModel::Folder::Functions))));
    QCOMPARE(tree.indexForKey(ProjectTreeModel::pouKey(added)).data().toString(), QStringLiteral("Alarm (PRG)"));
    QCOMPARE(tree.indexForKey(ProjectTreeModel::pouKey(PouId{4})).data().toString(), QStringLiteral("PLC_PRG (PRG)"));
}

void TestProjectTree::activatingAnActionAsksToOpenItsBody()
{
    ProjectModel projectModel;
    projectModel.reset(sampleProject());
    ProjectTreeModel tree(projectModel);
    ProjectTreeView view;
    view.setProjectModel(&tree);
    QSignalSpy open(&view, &ProjectTreeView::openRequested);

    Q_EMIT view.activated(tree.indexForKey(QStringLiteral("a:1:fill")));
    Q_EMIT view.activated(tree.indexForKey(ProjectTreeModel::folderKey(ProjectTreeModel::Folder::DataTypes)));

    QCOMPARE(open.count(), 1);
    const BodyRef expected{PouId{1}, BodyRef::Part::Action, QStringLiteral("Fill")};
    QCOMPARE(open.at(0).at(0).value<BodyRef>(), expected);
}

QTEST_MAIN(TestProjectTree)
#include "tst_projecttree.moc"
