#pragma once

#include "editors/globals/globallists.h"
#include "model/ids.h"

#include <QTabWidget>

namespace iec::model {
class ProjectModel;
struct Project;
} // namespace iec::model

namespace iec::editors {
class CodeEditor;
class DiagramEditor;
struct EditorFactory;
class ConfigurationEditor;
class GlobalListEditor;
class DataTypeEditor;
class DeclarationEditor;
class OnlineView;
struct DeclarationRow;
} // namespace iec::editors

namespace iec::app {

class AddDataTextEditor;
class MemberEditor;
class UndoStacks;

// The tabs in the middle of the window: one per open POU body, action or transition. Text bodies
// open in the ST/IL editor, which pushes what the user types into the model (the text document's
// own undo stays the authority while typing, DESIGN.md). A POU's own body has its declaration
// editor above it in a splitter (actions and transitions declare nothing); its edits go on the
// POU's undo stack. Tabs follow the model: a renamed POU retitles its tabs, a removed one closes
// them.
class DocumentArea : public QTabWidget
{
    Q_OBJECT

public:
    explicit DocumentArea(model::ProjectModel &projectModel, QWidget *parent = nullptr);

    // Opens the body in a tab (or shows its tab when it is open already); returns the tab's widget.
    QWidget *openBody(const model::BodyRef &ref);
    [[nodiscard]] QWidget *documentFor(const model::BodyRef &ref) const;
    [[nodiscard]] editors::CodeEditor *textEditorFor(const model::BodyRef &ref) const;
    // The graphical editor (LD, FBD, CFC, SFC) of an open body; nullptr for text or closed tabs.
    [[nodiscard]] editors::DiagramEditor *diagramEditorFor(const model::BodyRef &ref) const;
    [[nodiscard]] editors::DiagramEditor *currentDiagramEditor() const;
    // The settings' grid size for every graphical editor, open now or later.
    void setGridSize(int size);
    // The declaration editor of an open POU body; nullptr for actions, transitions, closed tabs.
    [[nodiscard]] editors::DeclarationEditor *declarationEditorFor(const model::BodyRef &ref) const;
    [[nodiscard]] std::optional<model::BodyRef> currentBody() const;
    // Opens the data type editor of `typeName` in a tab (or shows its tab); its edits go on the
    // project's undo stack. The tab follows renames of the type and closes when it is removed.
    QWidget *openDataType(const QString &typeName);
    [[nodiscard]] editors::DataTypeEditor *dataTypeEditorFor(const QString &typeName) const;
    [[nodiscard]] editors::DataTypeEditor *currentDataTypeEditor() const;
    // Opens the editor of a global variable list in a tab (or shows its tab); its edits go on the
    // project's undo stack, a rename of a global renames its uses. The tab follows renames of
    // the list and closes when it is deleted. (documentareainstances.cpp)
    QWidget *openGlobalList(const editors::GlobalListRef &list);
    [[nodiscard]] editors::GlobalListEditor *globalListEditorFor(const editors::GlobalListRef &list) const;
    // Go to definition of a global: opens the list that declares `variable` (the list named
    // `list` when given, CODESYS's List.Variable) at its row. False when no list declares it.
    bool showGlobalVariable(const QString &list, const QString &variable);
    // Opens the task configuration of `configuration` (or shows its tab) at the resource and task
    // given (the first when empty); its edits go on the project's undo stack.
    QWidget *openConfiguration(const QString &configuration, const QString &resource = {}, const QString &task = {});
    [[nodiscard]] editors::ConfigurationEditor *configurationEditorFor(const QString &configuration) const;
    // Opens method or property `name` of `pou` (CODESYS keeps them in the POU's addData) as
    // text in a tab, or shows its tab; nullptr when there is no such member. Its text goes into
    // the model as a body's does; online it is only looked at. (documentareamembers.cpp)
    QWidget *openMember(model::PouId pou, const QString &name);
    [[nodiscard]] MemberEditor *memberEditorFor(model::PouId pou, const QString &name) const;
    // Opens INTERFACE `name` (CODESYS keeps it in the project's addData) as text in a tab, in the
    // same way; nullptr when there is no such interface.
    QWidget *openInterface(const QString &name);
    // Go to definition of `path` (a dotted name) used in the body `from`: a variable of the POU
    // shows its declaration row, a member of a function block instance the row in that FB, a
    // POU opens, a data type opens its editor, an action or transition of the POU opens. False
    // when the name is not defined in the project (a keyword, a standard function, a global).
    bool goToDefinition(const model::BodyRef &from, const QString &path);
    // Auto-declare: what the Declare Variable dialog proposes for `name` used in body `ref` (class
    // VAR, the type guessed from the body), and the declaration itself: one step on the POU's
    // undo stack; false with the table's message when the row cannot be declared.
    [[nodiscard]] editors::DeclarationRow proposeDeclaration(const model::BodyRef &ref, const QString &name) const;
    bool declareVariable(const model::BodyRef &ref, const editors::DeclarationRow &row, QString *error = nullptr);
    // Shift+F2 in a body: the dialog for the name under the cursor when it is not declared yet.
    void autoDeclareInteractive(const model::BodyRef &ref);
    // The Declare Variable dialog for `name` used in body `ref` (a graphical editor asks for it);
    // a tooltip at `at` in `anchor` says when it is declared already or cannot be.
    void declareInteractive(const model::BodyRef &ref, const QString &name, QWidget *anchor, QPoint at = {});
    [[nodiscard]] std::optional<model::BodyRef> bodyAt(int index) const;
    // Every open editor that shows the running program (online mode), with the body it edits.
    struct OnlineDocument {
        model::BodyRef body;
        editors::OnlineView *view = nullptr;
    };
    [[nodiscard]] QList<OnlineDocument> onlineViews() const;
    // Sends text typed but not yet pushed (the editors wait for a pause) into the model.
    void flushEdits();
    // Online: the declaration and data type editors, open now or opened later, are only looked
    // at (fields read-only, buttons off, Ctrl+Z in the table ignored); editRefused is sent when
    // a change is tried. The body editors refuse edits themselves (OnlineView).
    void setEditingLocked(bool locked);
    [[nodiscard]] bool isEditingLocked() const { return m_editingLocked; }

    // Typing is not on any undo stack, so the window asks here whether there is unsaved typing:
    // an open editor's document is modified, or one was when its tab closed.
    [[nodiscard]] bool hasUnsavedTyping() const;
    // The project was saved (or replaced): what is typed so far counts as saved.
    void markTypingSaved();

    // Window → Next / Previous Document (wrapping around).
    void activateNext();
    void activatePrevious();
    void closeAll();

    static QString title(const model::Project &project, const model::BodyRef &ref);
    // Set on a tab that is one editor as a whole (a global list, a configuration): online it is
    // locked as a whole, as a data type tab is.
    static constexpr const char *kWholeTabEditorProperty = "iecWholeTabEditor";

Q_SIGNALS:
    // hasUnsavedTyping() may have changed.
    void typingModifiedChanged();
    // An editor's "Add to Watch" on a variable, with its full name ("Main.Count").
    void addToWatchRequested(const QString &name);
    // A graphical editor's online double-click: a value to prepare in the watch pane.
    void prepareValueRequested(const QString &name, const QString &literal);
    // Undo or redo was tried in a locked (online) declaration table.
    void editRefused();
    // A configuration editor's "Add List" for a resource (the window asks for the name).
    void addGlobalListRequested(const iec::editors::GlobalListRef &owner);

private:
    void closeDocumentsIf(const std::function<bool(const model::BodyRef &)> &shouldClose);
    void retitleDocuments();
    void updateTextFromModel(const model::BodyRef &ref);
    [[nodiscard]] model::BodyRef refOf(int index) const;
    QWidget *createEditor(const model::BodyRef &ref);
    QWidget *createBodyEditor(const model::BodyRef &ref);
    QWidget *createDiagramEditor(const editors::EditorFactory &factory, const model::BodyRef &ref);
    void closeDocument(int index);
    QWidget *addAddDataTab(AddDataTextEditor *editor); // a member or interface tab, wired

    model::ProjectModel &m_projectModel;
    UndoStacks *m_undoStacks;
    bool m_typingInClosedDocuments = false;
    bool m_editingLocked = false;
    int m_gridSize = 10;
};

} // namespace iec::app
