// Methods and properties in the window: the tree lists them under their function block, a
// double-click opens one as text, typing changes what the program computes, the text document's
// undo takes it back, text that does not read is marked and not taken, a new name in the header
// renames, and adding and deleting members are steps on the project's undo stack.
#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/interfaceeditor.h"
#include "app/mainwindow.h"
#include "app/membereditor.h"
#include "app/messagespane.h"
#include "app/projectcommands.h"
#include "app/projecttreeactions.h"
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "app/projectsearch.h"
#include "app/searchresultspane.h"
#include "app/undostacks.h"
#include "editors/text/codeeditor.h"
#include "interpreter/frontend/codesysmembers.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"
#include "model/projectmodel.h"
#include "testsettings.h"

#include <QAction>
#include <QTemporaryDir>
#include <QTest>
#include <QTextCursor>
#include <QUndoStack>

#include <algorithm>

using namespace iec;
using namespace iec::app;

namespace {

const QString kAdd = QStringLiteral("METHOD Add : INT\n"
                                    "VAR_INPUT\n"
                                    "    x : INT;\n"
                                    "END_VAR\n"
                                    "n := n + x;\n"
                                    "Add := n;\n"
                                    "END_METHOD\n");

const QString kSource = QStringLiteral("FUNCTION_BLOCK Counter\nVAR\n    n : INT;\nEND_VAR\n") + kAdd
    + QStringLiteral("PROPERTY Count : INT\nGET\nCount := n;\nEND_GET\nEND_PROPERTY\n"
                     "END_FUNCTION_BLOCK\n"
                     "PROGRAM Main\nVAR\n    c : Counter;\n    r : INT;\nEND_VAR\n"
                     "r := c.Add(2) + c.Count;\n"
                     "END_PROGRAM\n");

model::Project sampleProject()
{
    return interp::frontend::readIecText(kSource, QStringLiteral("Members")).project;
}

model::PouId counterId(const model::ProjectModel &model)
{
    return model.project().findPou(QStringLiteral("Counter"))->id;
}

// Main.r after each of three cycles, or the first compiler message.
QString runThreeCycles(const model::Project &project)
{
    interp::Diagnostics diagnostics;
    const auto module = interp::frontend::compileProject(project, diagnostics);
    if (!module)
        return diagnostics.all().empty() ? QStringLiteral("no module") : diagnostics.all().front().toString();
    interp::Runtime runtime(module);
    QStringList values;
    for (int cycle = 0; cycle < 3; ++cycle) {
        runtime.runCycle();
        values << runtime.read(*runtime.find(QStringLiteral("Main.r")));
    }
    return values.join(QLatin1Char(' '));
}

// Replaces `from` by `to` in the editor as typing does, then lets the pause pass.
void typeReplacing(editors::CodeEditor *editor, const QString &from, const QString &to)
{
    const qsizetype at = editor->toPlainText().indexOf(from);
    QVERIFY(at >= 0);
    QTextCursor cursor(editor->document());
    cursor.setPosition(int(at));
    cursor.setPosition(int(at + from.size()), QTextCursor::KeepAnchor);
    cursor.insertText(to);
    editor->flushPendingEdit();
}

MemberEditor *openFromTree(MainWindow &window, const QString &member)
{
    ProjectTreeView &tree = window.projectTree();
    auto *treeModel = qobject_cast<ProjectTreeModel *>(tree.model());
    const QModelIndex index = treeModel->indexForKey(ProjectTreeModel::memberKey(counterId(window.projectModel()), member));
    if (!index.isValid())
        return nullptr;
    Q_EMIT tree.activated(index);
    return qobject_cast<MemberEditor *>(window.documents().currentWidget());
}

} // namespace

class TestMemberDocuments : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void treeListsMembersUnderTheirBlock();
    void typingChangesWhatTheProgramComputes();
    void textThatDoesNotReadIsMarkedAndNotTaken();
    void aNewNameInTheHeaderRenames();
    void addingAndDeletingAreUndoSteps();
    void onlineTheTextIsOnlyLookedAt();
    void compilerMessagesAreMarkedInTheMember();
    void aPropertysMessagesGoToTheirAccessor();
    void findInProjectSearchesMembers();
    void interfacesAreEditedAsText();
    void addingAndDeletingInterfacesAreUndoSteps();
    void findInProjectSearchesInterfaces();

private:
    QTemporaryDir m_configHome;
};

void TestMemberDocuments::initTestCase()
{
    useTestSettings(m_configHome);
}

void TestMemberDocuments::treeListsMembersUnderTheirBlock()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    auto *treeModel = qobject_cast<ProjectTreeModel *>(window.projectTree().model());
    const model::PouId counter = counterId(window.projectModel());
    const QModelIndex add = treeModel->indexForKey(ProjectTreeModel::memberKey(counter, QStringLiteral("Add")));
    const QModelIndex count = treeModel->indexForKey(ProjectTreeModel::memberKey(counter, QStringLiteral("Count")));
    QVERIFY(add.isValid() && count.isValid());
    QCOMPARE(add.data().toString(), QStringLiteral("Add (METHOD)"));
    QCOMPARE(count.data().toString(), QStringLiteral("Count (PROPERTY)"));
    QCOMPARE(add.parent(), treeModel->indexForKey(ProjectTreeModel::pouKey(counter)));
    MemberEditor *editor = openFromTree(window, QStringLiteral("Add"));
    QVERIFY(editor);
    QCOMPARE(editor->editor()->toPlainText(), kAdd);
    QCOMPARE(window.documents().tabText(window.documents().currentIndex()), QStringLiteral("Counter.Add"));
    // Opened again, the same tab comes forward.
    const int tabs = window.documents().count();
    QCOMPARE(openFromTree(window, QStringLiteral("add")), editor);
    QCOMPARE(window.documents().count(), tabs);
}

void TestMemberDocuments::typingChangesWhatTheProgramComputes()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    const model::AddData before = window.projectModel().project().findPou(QStringLiteral("Counter"))->addData;
    QCOMPARE(runThreeCycles(window.projectModel().project()), QStringLiteral("4 8 12"));
    MemberEditor *editor = openFromTree(window, QStringLiteral("Add"));
    QVERIFY(editor);
    typeReplacing(editor->editor(), QStringLiteral("n := n + x;"), QStringLiteral("n := n + 10 * x;"));
    QCOMPARE(editor->editor()->diagnostics(), QList<editors::TextDiagnostic>());
    const model::Pou &counter = *window.projectModel().project().findPou(QStringLiteral("Counter"));
    QCOMPARE(interp::frontend::printCodesysMember(counter, QStringLiteral("Add")),
        QString(kAdd).replace(QStringLiteral("n + x"), QStringLiteral("n + 10 * x")));
    QCOMPARE(runThreeCycles(window.projectModel().project()), QStringLiteral("40 80 120"));
    QVERIFY(window.documents().hasUnsavedTyping());
    // The text document's undo is the authority while typing: it takes the edit back.
    editor->editor()->undo();
    editor->editor()->flushPendingEdit();
    QCOMPARE(editor->editor()->toPlainText(), kAdd);
    QCOMPARE(window.projectModel().project().findPou(QStringLiteral("Counter"))->addData.at(0).name, before.at(0).name);
    QCOMPARE(interp::frontend::printCodesysMember(*window.projectModel().project().findPou(QStringLiteral("Counter")),
                 QStringLiteral("Add")),
        kAdd);
    QCOMPARE(runThreeCycles(window.projectModel().project()), QStringLiteral("4 8 12"));
}

void TestMemberDocuments::textThatDoesNotReadIsMarkedAndNotTaken()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    MemberEditor *editor = openFromTree(window, QStringLiteral("Add"));
    QVERIFY(editor);
    const model::AddData before = window.projectModel().project().findPou(QStringLiteral("Counter"))->addData;
    typeReplacing(editor->editor(), QStringLiteral("n := n + x;"), QStringLiteral("n := n + ;"));
    const QList<editors::TextDiagnostic> marks = editor->editor()->diagnostics();
    QVERIFY(!marks.isEmpty());
    QCOMPARE(marks.front().line, 5);
    QCOMPARE(window.projectModel().project().findPou(QStringLiteral("Counter"))->addData, before);
    // Mended, it is taken and the mark goes.
    typeReplacing(editor->editor(), QStringLiteral("n := n + ;"), QStringLiteral("n := n + 2 * x;"));
    QCOMPARE(editor->editor()->diagnostics(), QList<editors::TextDiagnostic>());
    QCOMPARE(runThreeCycles(window.projectModel().project()), QStringLiteral("8 16 24"));
    // The name of another member is refused at the header.
    typeReplacing(editor->editor(), QStringLiteral("METHOD Add"), QStringLiteral("METHOD Count"));
    QVERIFY(!editor->editor()->diagnostics().isEmpty());
    QCOMPARE(editor->editor()->diagnostics().front().message,
        QStringLiteral("Counter already has a method or property called Count."));
    QCOMPARE(editor->name(), QStringLiteral("Add"));
}

void TestMemberDocuments::aNewNameInTheHeaderRenames()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    MemberEditor *editor = openFromTree(window, QStringLiteral("Add"));
    QVERIFY(editor);
    typeReplacing(editor->editor(), QStringLiteral("METHOD Add : INT"), QStringLiteral("METHOD Plus : INT"));
    typeReplacing(editor->editor(), QStringLiteral("Add := n;"), QStringLiteral("Plus := n;"));
    QCOMPARE(editor->name(), QStringLiteral("Plus"));
    QCOMPARE(window.documents().tabText(window.documents().indexOf(editor)), QStringLiteral("Counter.Plus"));
    auto *treeModel = qobject_cast<ProjectTreeModel *>(window.projectTree().model());
    const model::PouId counter = counterId(window.projectModel());
    QVERIFY(treeModel->indexForKey(ProjectTreeModel::memberKey(counter, QStringLiteral("Plus"))).isValid());
    QVERIFY(!treeModel->indexForKey(ProjectTreeModel::memberKey(counter, QStringLiteral("Add"))).isValid());
    // The method stays where it was: first.
    const auto members = interp::frontend::codesysMembers(*window.projectModel().project().findPou(counter));
    QCOMPARE(members.front().name, QStringLiteral("Plus"));
}

void TestMemberDocuments::addingAndDeletingAreUndoSteps()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    const model::PouId counter = counterId(window.projectModel());
    const model::Pou before = *window.projectModel().project().findPou(counter);
    QUndoStack &stack = window.undoStacks().projectStack();
    ProjectCommands &commands = window.projectCommands();
    QString error;
    QVERIFY(!commands.addMember(counter, QStringLiteral("count"), false, &error));
    QCOMPARE(error, QStringLiteral("This function block has a method or property named \"count\" already."));
    QVERIFY(!commands.addMember(window.projectModel().project().findPou(QStringLiteral("Main"))->id,
        QStringLiteral("Reset"), false, &error));
    QCOMPARE(error, QStringLiteral("Methods and properties belong to function blocks."));
    QVERIFY(commands.addMember(counter, QStringLiteral("Reset"), false));
    QVERIFY(commands.addMember(counter, QStringLiteral("Limit"), true));
    QCOMPARE(stack.count(), 2);
    QCOMPARE(stack.undoText(), QStringLiteral("Add Property Limit"));
    const model::Pou &now = *window.projectModel().project().findPou(counter);
    QCOMPARE(interp::frontend::printCodesysMember(now, QStringLiteral("Reset")),
        QStringLiteral("METHOD Reset : BOOL\nVAR_INPUT\nEND_VAR\nReset := TRUE;\nEND_METHOD\n"));
    QCOMPARE(interp::frontend::printCodesysMember(now, QStringLiteral("Limit")),
        QStringLiteral("PROPERTY Limit : INT\nGET\nLimit := 0;\nEND_GET\nSET\nEND_SET\nEND_PROPERTY\n"));
    QCOMPARE(runThreeCycles(window.projectModel().project()), QStringLiteral("4 8 12")); // still compiles
    // Its tab closes when it goes.
    MemberEditor *editor = openFromTree(window, QStringLiteral("Reset"));
    QVERIFY(editor);
    QVERIFY(commands.removeMember(counter, QStringLiteral("Reset")));
    QCOMPARE(stack.undoText(), QStringLiteral("Delete Reset"));
    QTRY_COMPARE(window.documents().indexOf(editor), -1);
    stack.undo();
    stack.undo();
    stack.undo();
    QCOMPARE(window.projectModel().project().findPou(counter)->addData, before.addData);
    stack.redo();
    QCOMPARE(interp::frontend::codesysMembers(*window.projectModel().project().findPou(counter)).size(), size_t(3));
}

void TestMemberDocuments::onlineTheTextIsOnlyLookedAt()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    MemberEditor *editor = openFromTree(window, QStringLiteral("Count"));
    QVERIFY(editor);
    QVERIFY(!editor->editor()->isReadOnly());
    window.documents().setEditingLocked(true);
    QVERIFY(editor->editor()->isReadOnly());
    window.documents().setEditingLocked(false);
    QVERIFY(!editor->editor()->isReadOnly());
}

void TestMemberDocuments::compilerMessagesAreMarkedInTheMember()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    MemberEditor *editor = openFromTree(window, QStringLiteral("Add"));
    QVERIFY(editor);
    // It reads as a method, so the model takes it; the compiler finds the unknown name, on the
    // member's line 6 (line 2 of its body).
    typeReplacing(editor->editor(), QStringLiteral("Add := n;"), QStringLiteral("Add := n + Cuont;"));
    QCOMPARE(editor->editor()->diagnostics(), QList<editors::TextDiagnostic>());
    QTRY_VERIFY_WITH_TIMEOUT(!editor->editor()->diagnostics().isEmpty(), 5000);
    const editors::TextDiagnostic mark = editor->editor()->diagnostics().front();
    QCOMPARE(mark.line, 6);
    QCOMPARE(mark.column, 12);
    QCOMPARE(mark.length, 5); // the whole name
    QVERIFY2(mark.message.contains(QStringLiteral("Cuont")), qPrintable(mark.message));
    // Closed and opened again, the tab shows the messages at once.
    window.documents().closeAll();
    editor = openFromTree(window, QStringLiteral("Add"));
    QVERIFY(editor);
    QCOMPARE(editor->editor()->diagnostics().size(), 1);
    QCOMPARE(editor->editor()->diagnostics().front().line, 6);
    // The Messages pane's entry opens the member at that line.
    window.documents().closeAll();
    const MessageListModel &messages = window.messagesPane().model();
    int row = 0;
    while (row < messages.rowCount() && messages.message(row).pouName != QStringLiteral("Counter.Add"))
        ++row;
    QVERIFY(row < messages.rowCount());
    window.buildController().openLocation(messages.message(row));
    editor = qobject_cast<MemberEditor *>(window.documents().currentWidget());
    QVERIFY(editor);
    QCOMPARE(editor->title(), QStringLiteral("Counter.Add"));
    QCOMPARE(editor->editor()->textCursor().blockNumber() + 1, 6);
    // Mended, the mark goes with the next compile.
    typeReplacing(editor->editor(), QStringLiteral(" + Cuont"), QString());
    QTRY_VERIFY_WITH_TIMEOUT(editor->editor()->diagnostics().isEmpty(), 5000);
}

namespace {

int lineOf(const editors::CodeEditor *editor, const QString &text)
{
    return editor->document()->find(text).blockNumber() + 1;
}

} // namespace

// A property with both a GET and a SET: the compiler names its bodies Counter.Count.GET and
// Counter.Count.SET, so each message is marked in its own body and the Messages pane opens it.
void TestMemberDocuments::aPropertysMessagesGoToTheirAccessor()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    MemberEditor *editor = openFromTree(window, QStringLiteral("Count"));
    QVERIFY(editor);
    typeReplacing(editor->editor(), QStringLiteral("Count := n;"), QStringLiteral("Count := n + Bad1;"));
    typeReplacing(editor->editor(), QStringLiteral("END_GET\n"), QStringLiteral("END_GET\nSET\nn := Count - Bad2;\nEND_SET\n"));
    QTRY_COMPARE_WITH_TIMEOUT(editor->editor()->diagnostics().size(), 2, 5000);
    QList<editors::TextDiagnostic> marks = editor->editor()->diagnostics();
    std::sort(marks.begin(), marks.end(), [](const auto &a, const auto &b) { return a.line < b.line; });
    QCOMPARE(marks[0].line, lineOf(editor->editor(), QStringLiteral("Bad1")));
    QCOMPARE(marks[0].column, 14);
    QVERIFY2(marks[0].message.contains(QStringLiteral("Bad1")), qPrintable(marks[0].message));
    QCOMPARE(marks[1].line, lineOf(editor->editor(), QStringLiteral("Bad2")));
    QCOMPARE(marks[1].column, 14);
    QVERIFY2(marks[1].message.contains(QStringLiteral("Bad2")), qPrintable(marks[1].message));
    QVERIFY(marks[0].line < marks[1].line);
    const int setterLine = marks[1].line;
    window.documents().closeAll();
    const MessageListModel &messages = window.messagesPane().model();
    int row = 0;
    while (row < messages.rowCount() && messages.message(row).pouName != QStringLiteral("Counter.Count.SET"))
        ++row;
    QVERIFY(row < messages.rowCount());
    window.buildController().openLocation(messages.message(row));
    editor = qobject_cast<MemberEditor *>(window.documents().currentWidget());
    QVERIFY(editor);
    QCOMPARE(editor->title(), QStringLiteral("Counter.Count"));
    QCOMPARE(editor->editor()->textCursor().blockNumber() + 1, setterLine);
}

void TestMemberDocuments::findInProjectSearchesMembers()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    const SearchResult result = ProjectSearch::find(window.projectModel().project(), {QStringLiteral("n + x")});
    QCOMPARE(result.hits.size(), size_t(1));
    const SearchHit &hit = result.hits.front();
    QCOMPARE(hit.place, QStringLiteral("Counter.Add"));
    QCOMPARE(hit.member, QStringLiteral("Add"));
    QCOMPARE(hit.line, 5);
    QCOMPARE(hit.column, 6);
    QVERIFY(showSearchHit(window.documents(), hit));
    auto *editor = qobject_cast<MemberEditor *>(window.documents().currentWidget());
    QVERIFY(editor);
    QCOMPARE(editor->editor()->textCursor().selectedText(), QStringLiteral("n + x"));
}


namespace {

const QString kShape = QStringLiteral("INTERFACE IShape\n"
                                      "METHOD Area : INT\n"
                                      "END_METHOD\n"
                                      "END_INTERFACE\n");

const QString kShapeSource = kShape
    + QStringLiteral("FUNCTION_BLOCK Square IMPLEMENTS IShape\nVAR\n    side : INT := 3;\nEND_VAR\n"
                     "METHOD Area : INT\nArea := side * side;\nEND_METHOD\n"
                     "END_FUNCTION_BLOCK\n"
                     "PROGRAM Main\nVAR\n    s : Square;\n    i : IShape;\n    r : INT;\nEND_VAR\n"
                     "i := s;\nr := r + i.Area();\n"
                     "END_PROGRAM\n");

InterfaceEditor *openInterfaceFromTree(MainWindow &window, const QString &name)
{
    ProjectTreeView &tree = window.projectTree();
    auto *treeModel = qobject_cast<ProjectTreeModel *>(tree.model());
    const QModelIndex index = treeModel->indexForKey(ProjectTreeModel::interfaceKey(name));
    if (!index.isValid())
        return nullptr;
    Q_EMIT tree.activated(index);
    return qobject_cast<InterfaceEditor *>(window.documents().currentWidget());
}

} // namespace

// An INTERFACE (CODESYS keeps it in the project's addData) is listed in the tree and edited as
// one text, as a method is: typing goes into the model after a pause, the text document's undo
// takes it back, text that does not read (or takes a POU's name) is marked and not taken, and a
// new name in the header renames it.
void TestMemberDocuments::interfacesAreEditedAsText()
{
    MainWindow window;
    window.projectModel().reset(interp::frontend::readIecText(kShapeSource, QStringLiteral("Shapes")).project);
    auto *treeModel = qobject_cast<ProjectTreeModel *>(window.projectTree().model());
    const QModelIndex node = treeModel->indexForKey(ProjectTreeModel::interfaceKey(QStringLiteral("IShape")));
    QVERIFY(node.isValid());
    QCOMPARE(node.data().toString(), QStringLiteral("IShape (ITF)"));
    QCOMPARE(node.parent(), treeModel->indexForKey(ProjectTreeModel::folderKey(ProjectTreeModel::Folder::Interfaces)));
    QCOMPARE(runThreeCycles(window.projectModel().project()), QStringLiteral("9 18 27"));
    InterfaceEditor *editor = openInterfaceFromTree(window, QStringLiteral("IShape"));
    QVERIFY(editor);
    QCOMPARE(editor->editor()->toPlainText(), kShape);
    QCOMPARE(window.documents().tabText(window.documents().currentIndex()), QStringLiteral("IShape"));
    QVERIFY(!editor->editor()->isReadOnly());
    // A prototype the block does not implement: taken, and the compiler says what is missing.
    typeReplacing(editor->editor(), QStringLiteral("END_INTERFACE"), QStringLiteral("METHOD Perimeter : INT\nEND_METHOD\nEND_INTERFACE"));
    QCOMPARE(interp::frontend::printCodesysInterface(window.projectModel().project(), QStringLiteral("IShape")),
        editor->editor()->toPlainText());
    QVERIFY(runThreeCycles(window.projectModel().project()).contains(QStringLiteral("Perimeter")));
    // The text document's undo takes it back, through the model.
    editor->editor()->undo();
    editor->editor()->flushPendingEdit();
    QCOMPARE(interp::frontend::printCodesysInterface(window.projectModel().project(), QStringLiteral("IShape")), kShape);
    QCOMPARE(runThreeCycles(window.projectModel().project()), QStringLiteral("9 18 27"));
    // Text that does not read is marked, not taken.
    const model::AddData before = window.projectModel().project().addData;
    typeReplacing(editor->editor(), QStringLiteral("END_METHOD"), QStringLiteral("END_METHD"));
    QVERIFY(!editor->editor()->diagnostics().isEmpty());
    QCOMPARE(window.projectModel().project().addData, before);
    typeReplacing(editor->editor(), QStringLiteral("END_METHD"), QStringLiteral("END_METHOD"));
    QVERIFY(editor->editor()->diagnostics().isEmpty());
    // A POU's name is refused at the header.
    typeReplacing(editor->editor(), QStringLiteral("INTERFACE IShape"), QStringLiteral("INTERFACE Square"));
    QCOMPARE(editor->editor()->diagnostics().size(), 1);
    QCOMPARE(editor->editor()->diagnostics().front().message, QStringLiteral("A POU or data type named \"Square\" exists already."));
    QCOMPARE(window.projectModel().project().addData, before);
    // A free name renames: the tab's title and the tree follow.
    typeReplacing(editor->editor(), QStringLiteral("INTERFACE Square"), QStringLiteral("INTERFACE IArea"));
    QCOMPARE(interp::frontend::codesysInterfaceNames(window.projectModel().project()), QStringList {QStringLiteral("IArea")});
    QCOMPARE(window.documents().tabText(window.documents().indexOf(editor)), QStringLiteral("IArea"));
    QVERIFY(treeModel->indexForKey(ProjectTreeModel::interfaceKey(QStringLiteral("IArea"))).isValid());
    // Online it is only looked at.
    window.documents().setEditingLocked(true);
    QVERIFY(editor->editor()->isReadOnly());
    window.documents().setEditingLocked(false);
    QVERIFY(!editor->editor()->isReadOnly());
}

void TestMemberDocuments::addingAndDeletingInterfacesAreUndoSteps()
{
    MainWindow window;
    window.projectModel().reset(interp::frontend::readIecText(kShapeSource, QStringLiteral("Shapes")).project);
    const model::AddData before = window.projectModel().project().addData;
    QUndoStack &stack = window.undoStacks().projectStack();
    ProjectCommands &commands = window.projectCommands();
    QString error;
    QVERIFY(!commands.addInterface(QStringLiteral("ishape"), &error));
    QCOMPARE(error, QStringLiteral("An interface named \"ishape\" exists already."));
    QVERIFY(!commands.addInterface(QStringLiteral("Main"), &error));
    QCOMPARE(error, QStringLiteral("A POU or data type named \"Main\" exists already."));
    QVERIFY(commands.addInterface(QStringLiteral("IMove")));
    QCOMPARE(stack.count(), 1);
    QCOMPARE(stack.undoText(), QStringLiteral("Add Interface IMove"));
    QCOMPARE(interp::frontend::printCodesysInterface(window.projectModel().project(), QStringLiteral("IMove")),
        QStringLiteral("INTERFACE IMove\nEND_INTERFACE\n"));
    // Typing still pending in its tab when an undo removes it does not bring it back (the monkey
    // found that).
    auto *typed = qobject_cast<InterfaceEditor *>(window.documents().openInterface(QStringLiteral("IMove")));
    QVERIFY(typed);
    QTextCursor cursor(typed->editor()->document());
    cursor.movePosition(QTextCursor::End);
    cursor.insertText(QStringLiteral("(* pending *)"));
    stack.undo();
    window.documents().flushEdits();
    QCOMPARE(window.projectModel().project().addData, before);
    QTRY_COMPARE(window.documents().indexOf(typed), -1);
    stack.redo();
    // A POU cannot take an interface's name.
    QVERIFY(!commands.addPou(NewPou {QStringLiteral("IMove")}, &error));
    QCOMPARE(error, QStringLiteral("An interface named \"IMove\" exists already."));
    // Its tab closes when it goes.
    InterfaceEditor *editor = openInterfaceFromTree(window, QStringLiteral("IShape"));
    QVERIFY(editor);
    QVERIFY(commands.removeInterface(QStringLiteral("IShape")));
    QCOMPARE(stack.undoText(), QStringLiteral("Delete IShape"));
    QTRY_COMPARE(window.documents().indexOf(editor), -1);
    QVERIFY(!window.documents().openInterface(QStringLiteral("IShape")));
    stack.undo();
    stack.undo();
    QCOMPARE(window.projectModel().project().addData, before);
    QVERIFY(window.documents().openInterface(QStringLiteral("IShape")));
    stack.redo();
    QCOMPARE(interp::frontend::codesysInterfaceNames(window.projectModel().project()),
        (QStringList {QStringLiteral("IShape"), QStringLiteral("IMove")}));
}

void TestMemberDocuments::findInProjectSearchesInterfaces()
{
    MainWindow window;
    window.projectModel().reset(interp::frontend::readIecText(kShapeSource, QStringLiteral("Shapes")).project);
    // The prototype is in Square's method and in the interface, in the tree's order.
    const SearchResult result = ProjectSearch::find(window.projectModel().project(), {QStringLiteral("area : int")});
    QCOMPARE(result.hits.size(), size_t(2));
    QCOMPARE(result.hits[0].place, QStringLiteral("Square.Area"));
    const SearchHit &hit = result.hits[1];
    QCOMPARE(hit.place, QStringLiteral("IShape"));
    QCOMPARE(hit.interfaceName, QStringLiteral("IShape"));
    QCOMPARE(hit.line, 2);
    QCOMPARE(hit.column, 8);
    QCOMPARE(hit.text, QStringLiteral("METHOD Area : INT"));
    QVERIFY(showSearchHit(window.documents(), hit));
    auto *editor = qobject_cast<InterfaceEditor *>(window.documents().currentWidget());
    QVERIFY(editor);
    QCOMPARE(window.documents().tabText(window.documents().currentIndex()), QStringLiteral("IShape"));
    QCOMPARE(editor->editor()->textCursor().selectedText(), QStringLiteral("Area : INT"));
}

QTEST_MAIN(TestMemberDocuments)
#include "tst_memberdocuments.moc"
