#pragma once

#include "editors/declarations/declarationrows.h"

#include <QPointer>
#include <QUndoStack>
#include <QWidget>

class QAction;
class QLabel;
class QTabWidget;
class QTableView;

namespace iec::editors {

class CodeEditor;
class DeclarationTableModel;

// Var lists edited as a table (name, class, type, initial value, address, comment) and as
// VAR ... END_VAR text, on two tabs, kept in sync. Every gesture (a cell edit, a row added,
// removed or moved, text applied after a pause or when the text loses focus) is validated and,
// when valid, handed to applyDeclarations(), which pushes one undo command. Problems are shown
// where they are (a tinted cell, an underline at the line and column) with the message below,
// and nothing is applied.
//
// What the declarations belong to is the subclass's business: a POU's interface
// (DeclarationEditor) or a global variable list (GlobalListEditor). A subclass reads them, applies
// them, may refuse list kinds or variables the generic checks accept, and calls refreshFromModel()
// when the model changed them (and once from its constructor).
class DeclarationEditorBase : public QWidget
{
    Q_OBJECT

public:
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
    // no variable of that name is declared here.
    bool showVariable(const QString &name);

protected:
    // `classes`: what the class cell offers, the first one for a new row in an empty table.
    DeclarationEditorBase(QUndoStack &undoStack, const QStringList &classes, QWidget *parent = nullptr);

    [[nodiscard]] virtual model::Interface declarations() const = 0;
    // Called with valid declarations that differ from declarations(); pushes one command.
    virtual void applyDeclarations(const model::Interface &declarations) = 0;
    // Checks the generic ones do not know: a list kind that does not belong here, a name that
    // clashes with something outside. Empty when fine.
    [[nodiscard]] virtual QString sectionProblem(const model::VarList &) const { return {}; }
    [[nodiscard]] virtual QString variableProblem(const model::VarList &, const model::Variable &) const { return {}; }

    void refreshFromModel();
    [[nodiscard]] QUndoStack *undoStack() const { return m_undoStack; }

    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    QWidget *createTablePage(const QStringList &classes);
    void retranslate();
    void fitColumns();
    void applyRows(const std::vector<DeclarationRow> &rows);
    void applyText();
    void apply(const model::Interface &declarations);
    void showProblem(const QString &message);
    [[nodiscard]] int currentRow() const;
    void selectRow(int row);
    // The subclass's checks of valid declarations: a problem of the list at `index` or of the
    // variable at `index` counted across the lists (= its row, = its entry in variablePlaces).
    struct Placed {
        bool section = false;
        int index = 0; // the list's index, or the variable's index across the lists
        QString message;
    };
    [[nodiscard]] std::vector<Placed> ownProblems(const model::Interface &declarations) const;

    QPointer<QUndoStack> m_undoStack; // the app drops a POU's stack when another project opens
    QString m_newRowClass;
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
    QStringList m_classes; // the class column's choices
};

} // namespace iec::editors
