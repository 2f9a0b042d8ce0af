// Global variable lists: the pure list operations as tables over configurations, and the list
// editor (the declaration editor's table and text on a GVL) driven as a user drives it, checking
// the model after redo/undo/redo.
#include "editors/declarations/declarationtablemodel.h"
#include "editors/declarations/declarationtext.h"
#include "editors/globals/globallisteditor.h"
#include "editors/globals/globallists.h"
#include "editors/text/codeeditor.h"
#include "model/projectmodel.h"

#include <QSignalSpy>
#include <QTableView>
#include <QTest>
#include <QUndoStack>

using namespace iec::editors;
using namespace iec::model;

namespace {

Variable variable(const QString &name, const QString &type, const QString &address = {})
{
    Variable v;
    v.name = name;
    v.type = {ElementaryType {type}};
    if (!address.isEmpty())
        v.address = address;
    return v;
}

VarList globals(const QString &name, std::vector<Variable> variables, bool constant = false, bool retain = false)
{
    VarList list;
    list.kind = VarListKind::Global;
    if (!name.isEmpty())
        list.name = name;
    list.constant = constant;
    list.retain = retain;
    list.variables = std::move(variables);
    return list;
}

// Configuration C: its own unnamed list; resource R: list IO in two sections (VAR_GLOBAL and
// CONSTANT, as CODESYS writes a GVL) and list HMI; a task started by IO.Start.
Project sampleProject()
{
    Project project;
    Pou main;
    main.name = QStringLiteral("Main");
    main.bodies.push_back(Body::withLanguage(BodyLanguage::ST));
    project.types.pous.push_back(main);
    Configuration configuration;
    configuration.name = QStringLiteral("C");
    configuration.globalVars.push_back(globals({}, {variable(QStringLiteral("Shared"), QStringLiteral("INT"))}));
    Resource resource;
    resource.name = QStringLiteral("R");
    resource.globalVars.push_back(globals(QStringLiteral("IO"),
        {variable(QStringLiteral("Start"), QStringLiteral("BOOL"), QStringLiteral("%IX0.0")),
            variable(QStringLiteral("Valve"), QStringLiteral("BOOL"), QStringLiteral("%QX0.0"))}));
    resource.globalVars.push_back(globals(QStringLiteral("HMI"), {variable(QStringLiteral("Count"), QStringLiteral("DINT"))}));
    resource.globalVars.push_back(
        globals(QStringLiteral("IO"), {variable(QStringLiteral("Limit"), QStringLiteral("INT"))}, true));
    Task task;
    task.name = QStringLiteral("OnStart");
    task.single = QStringLiteral("Start");
    resource.tasks.push_back(task);
    configuration.resources.push_back(resource);
    project.instances.configurations.push_back(configuration);
    return project;
}

const GlobalListRef kIo {QStringLiteral("C"), QStringLiteral("R"), QStringLiteral("IO")};
const GlobalListRef kHmi {QStringLiteral("C"), QStringLiteral("R"), QStringLiteral("HMI")};
const GlobalListRef kOwn {QStringLiteral("C"), {}, {}};

QStringList names(const std::vector<GlobalListRef> &lists)
{
    QStringList result;
    for (const GlobalListRef &list : lists)
        result << list.displayName();
    return result;
}

QStringList variableNames(const Interface &declarations)
{
    QStringList result;
    for (const VarList &list : declarations.varLists) {
        for (const Variable &v : list.variables)
            result << v.name;
    }
    return result;
}

void typeText(CodeEditor &editor, const QString &text)
{
    editor.selectAll();
    editor.insertPlainText(text);
}

} // namespace

class TestGlobals : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    // pure functions
    void listsGroupSectionsOfOneName();
    void declarationsReplaceTheListWhereItWas();
    void listOperations();
    void explicitConfigurationRunsTheImplicitProgram();

    // the editor
    void showsAListsSectionsInTableAndText();
    void cellEditIsOneCommandOnTheProjectStack();
    void constantAndRetainSectionsFromTheClassCell_data();
    void constantAndRetainSectionsFromTheClassCell();
    void textEditAppliesOneStep();
    void otherSectionsAreRefusedAtTheirPlace();
    void nameOfAnotherListIsRefused();
    void renamingAGlobalTakesItsTaskAlong();
    void followsARenameAndReportsRemoval();

private:
    std::unique_ptr<ProjectModel> m_model;
    std::unique_ptr<QUndoStack> m_stack;
    std::unique_ptr<GlobalListEditor> m_editor;

    [[nodiscard]] Interface listInModel() const
    {
        return globalListDeclarations(m_model->project().instances, kIo);
    }
    void checkRedoUndoRedo(const Instances &before, const Instances &after);
};

void TestGlobals::init()
{
    m_model = std::make_unique<ProjectModel>();
    m_model->reset(sampleProject());
    m_stack = std::make_unique<QUndoStack>();
    m_editor = std::make_unique<GlobalListEditor>(*m_model, kIo, *m_stack);
    m_editor->textEditor()->setEditDebounceInterval(60000);
    m_editor->resize(800, 300);
}

void TestGlobals::cleanup()
{
    m_editor.reset();
    m_stack.reset();
    m_model.reset();
}

void TestGlobals::checkRedoUndoRedo(const Instances &before, const Instances &after)
{
    QCOMPARE(m_stack->count(), 1);
    QCOMPARE(m_model->project().instances, after);
    m_stack->undo();
    QCOMPARE(m_model->project().instances, before);
    QCOMPARE(m_editor->tableModel()->rows(), rowsFromInterface(listInModel()));
    QCOMPARE(m_editor->textEditor()->toPlainText(), declarationText(listInModel()));
    m_stack->redo();
    QCOMPARE(m_model->project().instances, after);
    QCOMPARE(m_editor->tableModel()->rows(), rowsFromInterface(listInModel()));
}

// ---- pure functions ---------------------------------------------------------------------------

void TestGlobals::listsGroupSectionsOfOneName()
{
    const Instances instances = sampleProject().instances;
    QCOMPARE(names(globalLists(instances)), (QStringList {QStringLiteral("C"), QStringLiteral("IO"), QStringLiteral("HMI")}));
    QCOMPARE(globalLists(instances)[0], kOwn);
    const Interface io = globalListDeclarations(instances, kIo);
    QCOMPARE(io.varLists.size(), size_t(2));
    QVERIFY(io.varLists[1].constant);
    QCOMPARE(variableNames(io), (QStringList {QStringLiteral("Start"), QStringLiteral("Valve"), QStringLiteral("Limit")}));
    // Names compare as IEC names do.
    QVERIFY(globalListExists(instances, {QStringLiteral("c"), QStringLiteral("r"), QStringLiteral("io")}));
    QVERIFY(!globalListExists(instances, {QStringLiteral("C"), QStringLiteral("R"), QStringLiteral("Other")}));
}

void TestGlobals::declarationsReplaceTheListWhereItWas()
{
    const Instances instances = sampleProject().instances;
    Interface changed;
    changed.varLists.push_back(globals({}, {variable(QStringLiteral("Pump"), QStringLiteral("BOOL"))}, false, true));
    const auto result = withGlobalListDeclarations(instances, kIo, changed);
    QVERIFY(result);
    const std::vector<VarList> &lists = result->configurations[0].resources[0].globalVars;
    // IO's two sections became one RETAIN section named IO, in IO's place, before HMI.
    QCOMPARE(lists.size(), size_t(2));
    QCOMPARE(lists[0], globals(QStringLiteral("IO"), {variable(QStringLiteral("Pump"), QStringLiteral("BOOL"))}, false, true));
    QCOMPARE(lists[1].name, std::optional(QStringLiteral("HMI")));
    // Emptied, the list stays (it is deleted from the tree, not by emptying it).
    const auto emptied = withGlobalListDeclarations(instances, kHmi, {});
    QVERIFY(emptied && globalListExists(*emptied, kHmi));
    QVERIFY(!withGlobalListDeclarations(instances, {QStringLiteral("C"), QStringLiteral("R"), QStringLiteral("X")}, {}));
}

void TestGlobals::listOperations()
{
    const Instances instances = sampleProject().instances;
    const auto added = withGlobalListAdded(instances, kIo, QStringLiteral("Motors"));
    QVERIFY(added);
    QCOMPARE(added->list, (GlobalListRef {QStringLiteral("C"), QStringLiteral("R"), QStringLiteral("Motors")}));
    QCOMPARE(names(globalLists(added->instances)),
        (QStringList {QStringLiteral("C"), QStringLiteral("IO"), QStringLiteral("HMI"), QStringLiteral("Motors")}));

    const auto renamed = withGlobalListRenamed(instances, kIo, QStringLiteral("Plant"));
    QVERIFY(renamed);
    QCOMPARE(names(globalLists(renamed->instances)),
        (QStringList {QStringLiteral("C"), QStringLiteral("Plant"), QStringLiteral("HMI")}));
    QCOMPARE(globalListDeclarations(renamed->instances, renamed->list).varLists.size(), size_t(2));

    const auto copy = withGlobalListDuplicated(instances, kIo, QStringLiteral("IO_1"));
    QVERIFY(copy);
    // The copy's sections follow the original's last section.
    QCOMPARE(names(globalLists(copy->instances)),
        (QStringList {QStringLiteral("C"), QStringLiteral("IO"), QStringLiteral("HMI"), QStringLiteral("IO_1")}));
    Interface copied = globalListDeclarations(copy->instances, copy->list);
    QCOMPARE(variableNames(copied), variableNames(globalListDeclarations(instances, kIo)));
    QCOMPARE(copy->instances.configurations[0].resources[0].globalVars[3].name, std::optional(QStringLiteral("IO_1")));

    const auto removed = withGlobalListRemoved(instances, kIo);
    QVERIFY(removed);
    QCOMPARE(names(globalLists(*removed)), (QStringList {QStringLiteral("C"), QStringLiteral("HMI")}));
    QVERIFY(!withGlobalListRemoved(*removed, kIo));

    QCOMPARE(otherListDeclaring(instances, QStringLiteral("C"), QStringLiteral("count"), kIo), std::optional(kHmi));
    QCOMPARE(otherListDeclaring(instances, QStringLiteral("C"), QStringLiteral("Count"), kHmi), std::nullopt);
}

void TestGlobals::explicitConfigurationRunsTheImplicitProgram()
{
    Project project = sampleProject();
    project.instances = {};
    QCOMPARE(implicitProgram(project), QStringLiteral("Main"));
    const Instances explicitOne = withExplicitConfiguration(project.instances, QStringLiteral("Main"));
    QCOMPARE(explicitOne.configurations.size(), size_t(1));
    const Task &task = explicitOne.configurations[0].resources.at(0).tasks.at(0);
    QCOMPARE(task.interval, std::optional(QStringLiteral("T#10ms")));
    QCOMPARE(task.pouInstances.at(0).typeName, QStringLiteral("Main"));
    QCOMPARE(defaultGlobalListOwner(explicitOne),
        std::optional(GlobalListRef {QStringLiteral("Config"), QStringLiteral("Resource"), {}}));
    // A configured project stays as it is.
    QCOMPARE(withExplicitConfiguration(sampleProject().instances, QStringLiteral("Main")), sampleProject().instances);
}

// ---- the editor -------------------------------------------------------------------------------

void TestGlobals::showsAListsSectionsInTableAndText()
{
    const std::vector<DeclarationRow> rows = m_editor->tableModel()->rows();
    QCOMPARE(rows.size(), size_t(3));
    QCOMPARE(rows[0], (DeclarationRow {QStringLiteral("Start"), QStringLiteral("VAR_GLOBAL"), QStringLiteral("BOOL"), {},
                          QStringLiteral("%IX0.0"), {}}));
    QCOMPARE(rows[2].varClass, QStringLiteral("VAR_GLOBAL CONSTANT"));
    QCOMPARE(m_editor->textEditor()->toPlainText(), QStringLiteral("VAR_GLOBAL\n"
                                                                   "    Start AT %IX0.0 : BOOL;\n"
                                                                   "    Valve AT %QX0.0 : BOOL;\n"
                                                                   "END_VAR\n"
                                                                   "\n"
                                                                   "VAR_GLOBAL CONSTANT\n"
                                                                   "    Limit : INT;\n"
                                                                   "END_VAR\n"));
    // The class column shows its longest choice whole.
    const QTableView *table = m_editor->table();
    QVERIFY(table->columnWidth(int(DeclarationColumn::Class))
        > table->fontMetrics().horizontalAdvance(QStringLiteral("VAR_GLOBAL RETAIN PERSISTENT")));
}

void TestGlobals::cellEditIsOneCommandOnTheProjectStack()
{
    const Instances before = m_model->project().instances;
    DeclarationTableModel *table = m_editor->tableModel();
    QVERIFY(table->setData(table->index(1, int(DeclarationColumn::Address)), QStringLiteral("%QX0.3")));
    QCOMPARE(m_editor->problemText(), QString());
    Instances after = before;
    after.configurations[0].resources[0].globalVars[0].variables[1].address = QStringLiteral("%QX0.3");
    checkRedoUndoRedo(before, after);
    // An invalid address is marked and changes nothing.
    QVERIFY(table->setData(table->index(1, int(DeclarationColumn::Address)), QStringLiteral("%ZX1")));
    QCOMPARE(m_stack->count(), 1);
    QCOMPARE(m_editor->problemText(),
        QStringLiteral("Row 2: \"%ZX1\" is not an address such as %IX0.0, %QW3 or %MD10."));
}

void TestGlobals::constantAndRetainSectionsFromTheClassCell_data()
{
    QTest::addColumn<QString>("varClass");
    QTest::addColumn<bool>("constant");
    QTest::addColumn<bool>("retain");
    QTest::addColumn<bool>("persistent");
    QTest::addColumn<int>("sections"); // Valve (row 1) joins the CONSTANT section of Limit after it
    QTest::newRow("retain") << QStringLiteral("VAR_GLOBAL RETAIN") << false << true << false << 3;
    QTest::newRow("constant") << QStringLiteral("VAR_GLOBAL CONSTANT") << true << false << false << 2;
    QTest::newRow("persistent") << QStringLiteral("VAR_GLOBAL PERSISTENT") << false << false << true << 3;
    QTest::newRow("retain persistent") << QStringLiteral("VAR_GLOBAL RETAIN PERSISTENT") << false << true << true << 3;
}

void TestGlobals::constantAndRetainSectionsFromTheClassCell()
{
    QFETCH(QString, varClass);
    QFETCH(bool, constant);
    QFETCH(bool, retain);
    QFETCH(bool, persistent);
    QFETCH(int, sections);
    QVERIFY(GlobalListEditor::globalClasses().contains(varClass));
    const Instances before = m_model->project().instances;
    DeclarationTableModel *table = m_editor->tableModel();
    QVERIFY(table->setData(table->index(1, int(DeclarationColumn::Class)), varClass));
    QCOMPARE(m_editor->problemText(), QString());
    const Interface list = listInModel();
    QCOMPARE(list.varLists.size(), size_t(sections));
    QCOMPARE(list.varLists[1].constant, constant);
    QCOMPARE(list.varLists[1].retain, retain);
    QCOMPARE(list.varLists[1].persistent, persistent);
    QCOMPARE(list.varLists[1].variables.at(0).name, QStringLiteral("Valve"));
    QCOMPARE(table->data(table->index(1, int(DeclarationColumn::Class))).toString(), varClass);
    for (const VarList &section : list.varLists)
        QCOMPARE(section.name, std::optional(QStringLiteral("IO")));
    QCOMPARE(m_stack->count(), 1);
    m_stack->undo();
    QCOMPARE(m_model->project().instances, before);
}

void TestGlobals::textEditAppliesOneStep()
{
    const Instances before = m_model->project().instances;
    m_editor->showText();
    typeText(*m_editor->textEditor(),
        QStringLiteral("VAR_GLOBAL\n    Start AT %IX0.0 : BOOL;\n    Level AT %IW2 : INT; (* tank *)\nEND_VAR\n"
                       "VAR_GLOBAL RETAIN\n    Total : DINT := 0;\nEND_VAR\n"));
    QCOMPARE(m_stack->count(), 0); // not before the pause
    m_editor->flushPendingEdit();
    QCOMPARE(m_editor->problemText(), QString());
    const Interface list = listInModel();
    QCOMPARE(variableNames(list), (QStringList {QStringLiteral("Start"), QStringLiteral("Level"), QStringLiteral("Total")}));
    QCOMPARE(list.varLists[0].variables[1].address, std::optional(QStringLiteral("%IW2")));
    QCOMPARE(list.varLists[0].variables[1].documentation->text, QStringLiteral("tank"));
    QVERIFY(list.varLists[1].retain);
    QCOMPARE(m_editor->tableModel()->rows().size(), size_t(3));
    QCOMPARE(m_stack->count(), 1);
    m_stack->undo();
    QCOMPARE(m_model->project().instances, before);
}

void TestGlobals::otherSectionsAreRefusedAtTheirPlace()
{
    const Instances before = m_model->project().instances;
    typeText(*m_editor->textEditor(), QStringLiteral("VAR_GLOBAL\n    Start : BOOL;\nEND_VAR\nVAR_INPUT\n    x : INT;\nEND_VAR\n"));
    m_editor->flushPendingEdit();
    QCOMPARE(m_model->project().instances, before);
    QCOMPARE(m_editor->problemText(),
        QStringLiteral("Line 4, column 1: A global variable list holds VAR_GLOBAL sections only; VAR_INPUT belongs in a POU."));
    QCOMPARE(m_editor->textEditor()->diagnostics().value(0).line, 4);

    DeclarationTableModel *table = m_editor->tableModel();
    QVERIFY(table->setData(table->index(2, int(DeclarationColumn::Class)), QStringLiteral("VAR")));
    QCOMPARE(m_model->project().instances, before);
    QCOMPARE(m_editor->problemText(),
        QStringLiteral("Row 3: A global variable list holds VAR_GLOBAL sections only; VAR belongs in a POU."));
    QVERIFY(table->data(table->index(2, int(DeclarationColumn::Class)), Qt::BackgroundRole).isValid());
}

void TestGlobals::nameOfAnotherListIsRefused()
{
    const Instances before = m_model->project().instances;
    DeclarationTableModel *table = m_editor->tableModel();
    QVERIFY(table->setData(table->index(1, int(DeclarationColumn::Name)), QStringLiteral("Count")));
    QCOMPARE(m_model->project().instances, before);
    QCOMPARE(m_editor->problemText(), QStringLiteral("Row 2: Count is declared in the global variable list HMI already."));
    QVERIFY(table->data(table->index(1, int(DeclarationColumn::Name)), Qt::BackgroundRole).isValid());
}

void TestGlobals::renamingAGlobalTakesItsTaskAlong()
{
    std::vector<std::vector<QString>> seen;
    m_editor->setRenameReferences([&](const std::vector<VariableRename> &renames, QUndoCommand *) {
        std::vector<QString> pairs;
        for (const VariableRename &rename : renames)
            pairs.push_back(rename.oldName + QStringLiteral("->") + rename.newName);
        seen.push_back(pairs);
    });
    const Instances before = m_model->project().instances;
    DeclarationTableModel *table = m_editor->tableModel();
    QVERIFY(table->setData(table->index(0, int(DeclarationColumn::Name)), QStringLiteral("Go")));
    QCOMPARE(seen, (std::vector<std::vector<QString>> {{QStringLiteral("Start->Go")}}));
    Instances after = before;
    after.configurations[0].resources[0].globalVars[0].variables[0].name = QStringLiteral("Go");
    after.configurations[0].resources[0].tasks[0].single = QStringLiteral("Go");
    checkRedoUndoRedo(before, after);
    QCOMPARE(m_stack->undoText(), QStringLiteral("Rename global variable Start to Go"));
}

void TestGlobals::followsARenameAndReportsRemoval()
{
    QSignalSpy renamed(m_editor.get(), &GlobalListEditor::listRenamed);
    QSignalSpy removed(m_editor.get(), &GlobalListEditor::listRemoved);
    auto renaming = withGlobalListRenamed(m_model->project().instances, kIo, QStringLiteral("Plant"));
    m_model->setInstances(renaming->instances);
    QCOMPARE(renamed.count(), 1);
    QCOMPARE(m_editor->list().name, QStringLiteral("Plant"));
    QCOMPARE(m_editor->tableModel()->rows().size(), size_t(3));
    m_model->setInstances(*withGlobalListRemoved(m_model->project().instances, m_editor->list()));
    QCOMPARE(removed.count(), 1);
}

QTEST_MAIN(TestGlobals)
#include "tst_globals.moc"
