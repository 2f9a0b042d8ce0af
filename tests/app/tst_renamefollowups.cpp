// What renames and undo left open: a struct member renamed in the data type editor renames its
// uses in one step; an open body rewritten by a rename keeps its cursor; renaming an action
// renames the step actions (entry, exit, active) that name it; Edit → Undo acts on the part with
// the focus.
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/projectcommands.h"
#include "app/referencerename.h"
#include "app/undoactions.h"
#include "app/undostacks.h"
#include "editors/datatypes/datatypeeditor.h"
#include "editors/datatypes/kindpages.h"
#include "editors/datatypes/rowtable.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/text/codeeditor.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"
#include "testsettings.h"
#include "model/sfcoptions.h"

#include <QAction>
#include <QApplication>
#include <QSettings>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QUndoStack>

using namespace iec;
using namespace iec::app;

namespace {

const char *const kSource = R"(TYPE Point : STRUCT
  x : INT;
  y : INT;
END_STRUCT;
END_TYPE
PROGRAM Main
VAR
  p : Point;
  Count : INT;
END_VAR
p.x := p.y + 1;
  Count := Count + 1;
END_PROGRAM
PROGRAM Chart
INITIAL_STEP Init:
END_STEP
TRANSITION FROM Init TO Init
  := TRUE;
END_TRANSITION
END_PROGRAM
)";

model::Project sampleProject()
{
    model::Project project = interp::frontend::readIecText(QString::fromUtf8(kSource), QStringLiteral("T")).project;
    for (model::Pou &pou : project.types.pous) {
        if (pou.name != QLatin1String("Chart"))
            continue;
        model::PouPart fill;
        fill.name = QStringLiteral("Fill");
        fill.body = model::Body::withLanguage(model::BodyLanguage::ST);
        pou.actions.push_back(fill);
        for (model::Element &element : *pou.bodies.front().elements()) {
            if (auto *step = std::get_if<model::Step>(&element)) {
                model::StepOptions options;
                options.entryAction = QStringLiteral("Fill");
                options.activeAction = QStringLiteral("fill");
                options.exitAction = QStringLiteral("Other");
                model::setStepOptions(*step, options);
            }
        }
    }
    return project;
}

model::PouId idOf(const model::ProjectModel &model, const char *name)
{
    return model.project().findPou(QString::fromLatin1(name))->id;
}

} // namespace

class TestRenameFollowups : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void memberRenameInTheDataTypeEditorRenamesUses();
    void cursorStaysWhenARenameRewritesTheBody();
    void actionRenameReachesStepActions();
    void undoActsOnThePartWithFocus();

private:
    QTemporaryDir m_configHome;
};

void TestRenameFollowups::initTestCase()
{
    useTestSettings(m_configHome);
}

void TestRenameFollowups::memberRenameInTheDataTypeEditorRenamesUses()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    auto *editor = qobject_cast<editors::DataTypeEditor *>(window.documents().openDataType(QStringLiteral("Point")));
    QVERIFY(editor);
    auto *page = static_cast<editors::StructPage *>(editor->page(editors::TypeKind::Struct));
    page->members()->table()->item(0, 0)->setText(QStringLiteral("px"));
    QUndoStack &stack = window.undoStacks().projectStack();
    QCOMPARE(stack.count(), 1);
    QCOMPARE(stack.undoText(), QStringLiteral("Rename member x to px"));
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QCOMPARE(main->body()->text().section(QLatin1Char('\n'), 0, 0), QStringLiteral("p.px := p.y + 1;"));
    stack.undo();
    QCOMPARE(window.projectModel().project().findPou(QStringLiteral("Main"))->body()->text().section(QLatin1Char('\n'), 0, 0),
        QStringLiteral("p.x := p.y + 1;"));
}

void TestRenameFollowups::cursorStaysWhenARenameRewritesTheBody()
{
    MainWindow window;
    window.projectModel().reset(sampleProject());
    const model::BodyRef main {idOf(window.projectModel(), "Main"), model::BodyRef::Part::Pou, {}};
    window.documents().openBody(main);
    editors::CodeEditor *editor = window.documents().textEditorFor(main);
    editor->goToLine(2, 12); // on "Count + 1"
    window.undoStacks().pouStack(main.pou).push(
        createRenameVariableCommand(window.projectModel(), main.pou, QStringLiteral("Count"), QStringLiteral("N")));
    QCOMPARE(editor->document()->findBlockByNumber(1).text(), QStringLiteral("  N := N + 1;"));
    QCOMPARE(editor->textCursor().blockNumber(), 1);
    QCOMPARE(editor->textCursor().positionInBlock(), 11);
}

void TestRenameFollowups::actionRenameReachesStepActions()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    ProjectCommands commands(model, stack);
    const model::PouId chart = idOf(model, "Chart");
    QVERIFY(commands.rename({chart, model::BodyRef::Part::Action, QStringLiteral("Fill")}, QStringLiteral("Filling")));
    const auto stepOptions = [&] {
        for (const model::Element &element : *model.project().findPou(chart)->body()->elements()) {
            if (const auto *step = std::get_if<model::Step>(&element))
                return model::stepOptions(*step);
        }
        return model::StepOptions {};
    };
    QCOMPARE(stepOptions().entryAction, QStringLiteral("Filling"));
    QCOMPARE(stepOptions().activeAction, QStringLiteral("Filling"));
    QCOMPARE(stepOptions().exitAction, QStringLiteral("Other"));
    stack.undo();
    QCOMPARE(stepOptions().entryAction, QStringLiteral("Fill"));
    QCOMPARE(stepOptions().activeAction, QStringLiteral("fill"));
}

void TestRenameFollowups::undoActsOnThePartWithFocus()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.projectModel().reset(sampleProject());
    const model::BodyRef main {idOf(window.projectModel(), "Main"), model::BodyRef::Part::Pou, {}};
    window.documents().openBody(main);
    editors::DeclarationEditor *declarations = window.documents().declarationEditorFor(main);
    QAction *undo = window.findChild<QAction *>(QStringLiteral("undoAction"));
    QVERIFY(undo);

    // The declaration text being typed undoes its typing.
    declarations->showText();
    declarations->textEditor()->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget *>(declarations->textEditor()));
    QCOMPARE(undo->text(), QStringLiteral("&Undo Typing"));
    // The table undoes the POU's commands.
    declarations->showTable();
    declarations->table()->setFocus();
    QTRY_COMPARE(QApplication::focusWidget(), static_cast<QWidget *>(declarations->table()));
    QCOMPARE(undo->text(), QStringLiteral("&Undo"));
    // The body undoes its typing.
    window.documents().textEditorFor(main)->setFocus();
    QTRY_COMPARE(undo->text(), QStringLiteral("&Undo Typing"));
}

QTEST_MAIN(TestRenameFollowups)
#include "tst_renamefollowups.moc"
