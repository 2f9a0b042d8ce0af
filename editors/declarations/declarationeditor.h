#pragma once

#include "editors/declarations/declarationrows.h"

#include "model/ids.h"
#include "model/undo/variablerename.h"

#include <QPointer>
#include <QUndoStack>
#include <QWidget>

#include <functional>

class QAction;
class QLabel;
class QTabWidget;
class QTableView;

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {

class CodeEditor;
class DeclarationTableModel;

// The declarations of one POU, above its body as in CODESYS: a table (name, class, type, initial
// value, address, comment) and the same declarations as VAR ... END_VAR text, on two tabs. Both
// edit the model's Interface: every gesture (a cell edit, a row added, removed or moved, text
// applied after a pause or when the text loses focus) is validated and, when valid, pushed as one
// SetInterfaceCommand on `undoStack`. Problems are shown where they are (a tinted cell, an
// underline at the line and column) with the message below, and nothing is applied. Changes from
// elsewhere (undo, a rename) refresh both views.
class DeclarationEditor : public QWidget
{
    Q_OBJECT

public:
    DeclarationEditor(
        model::ProjectModel &projectModel, model::PouId pou, QUndoStack &undoStack, QWidget *parent = nullptr);

    // Adds to a gesture that renames variables what else the renames change (their uses in the
    // bodies); called before the gesture is pushed, while the model still has the old names.
    using RenameReferences = std::function<void(
        model::PouId pou, const std::vector<model::VariableRename> &renames, QUndoCommand *gesture)>;
    // The app provides it (app/referencerename); without one a rename changes the declarations only.
    void setRenameReferences(RenameReferences renameReferences) { m_renameReferences = std::move(renameReferences); }

    [[nodiscard]] model::PouId pou() const { return m_pou; }
    [[nodiscard]] QTabWidget *views() const { return m_views; }
    [[nodiscard]] QTableView *table() const { return m_table; }
    [[nodiscard]] DeclarationTableModel *tableModel() const { return m_tableModel; }
    [[nodiscard]] CodeEditor *textEditor() const { return m_text; }
    // The message of the first problem, empty when the shown declarations are valid.
    [[nodiscard]] QString problemText() const;

    void showTable();
    void showText();

    // Table gestures; the row is the current one (or the end when none is current).
    void addRow();
    void removeCurrentRow();
    void moveCurrentRow(int delta);

    // Applies text typed but not yet applied (the text waits for a pause).
    void flushPendingEdit();
    // Go to definition: shows the table with the variable's row current and focused. False when
    // the POU declares no variable of that name.
    bool showVariable(const QString &name);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    QWidget *createTablePage();
    void retranslate();
    [[nodiscard]] model::Interface currentInterface() const;
    void refreshFromModel();
    void fitColumns();
    void applyRows(const std::vector<DeclarationRow> &rows);
    void applyText();
    void apply(const model::Interface &declarations);
    void showProblem(const QString &message);
    [[nodiscard]] int currentRow() const;
    void selectRow(int row);

    model::ProjectModel &m_projectModel;
    model::PouId m_pou;
    QPointer<QUndoStack> m_undoStack; // the app drops a POU's stack when another project opens
    QTabWidget *m_views = nullptr;
    QTableView *m_table = nullptr;
    DeclarationTableModel *m_tableModel = nullptr;
    CodeEditor *m_text = nullptr;
    QLabel *m_problem = nullptr;
    QAction *m_addAction = nullptr;
    QAction *m_removeAction = nullptr;
    QAction *m_moveUpAction = nullptr;
    QAction *m_moveDownAction = nullptr;
    bool m_columnsFitted = false;
    RenameReferences m_renameReferences;
};

} // namespace iec::editors
