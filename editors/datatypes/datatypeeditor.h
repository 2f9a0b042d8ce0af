#pragma once

#include "editors/datatypes/datatypeform.h"
#include "editors/datatypes/datatypevalidation.h"

#include "model/undo/variablerename.h"

#include <QWidget>

#include <array>
#include <functional>

class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QUndoCommand;
class QStackedWidget;
class QUndoStack;

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {

class KindPage;
class MessageLabel;

// Edits one data type of the project: its name, its kind with that kind's form, and its initial
// value, with the IEC text of the type below. Every gesture (a field left with Enter or Tab, a
// table cell committed, a row added, removed or moved, a kind chosen) is validated; a valid edit
// goes onto `undoStack` as one ChangeDataTypeCommand, an invalid one shows its messages next to
// the fields and leaves the model alone. Changes made elsewhere (undo, redo) refresh the form.
class DataTypeEditor : public QWidget
{
    Q_OBJECT

public:
    DataTypeEditor(
        model::ProjectModel &projectModel, QString typeName, QUndoStack *undoStack, QWidget *parent = nullptr);

    // The name the type has in the model now (it follows renames, from here or from undo).
    [[nodiscard]] QString typeName() const { return m_typeName; }
    // What the fields show, applied or not.
    [[nodiscard]] DataTypeForm form() const;
    // The messages of the last check (empty: the fields are what the model holds).
    [[nodiscard]] const std::vector<FormError> &errors() const { return m_errors; }

    [[nodiscard]] QLineEdit *nameEdit() const { return m_name; }
    [[nodiscard]] QComboBox *kindBox() const { return m_kind; }
    [[nodiscard]] KindPage *page(TypeKind kind) const { return m_pages[size_t(kind)]; }
    [[nodiscard]] QLineEdit *initialValueEdit() const { return m_initialValue; }
    [[nodiscard]] QPlainTextEdit *preview() const { return m_preview; }

    // Adds to a gesture that renames members of struct `typeName` what else the renames change
    // (`x.Member` in the bodies, member names in initial values); called before the gesture is
    // pushed. The app provides it (app/referencerename); without one only the type changes.
    using RenameMembers = std::function<void(
        const QString &typeName, const std::vector<model::VariableRename> &renames, QUndoCommand *gesture)>;
    void setRenameMembers(RenameMembers renameMembers) { m_renameMembers = std::move(renameMembers); }

Q_SIGNALS:
    // For the tab title.
    void typeRenamed(const QString &newName);
    // The type is no longer in the project: the tab should close.
    void typeRemoved();

private:
    void buildPages();
    void loadFromModel();
    void loadForm(const DataTypeForm &form);
    void kindChosen(int index);
    void apply();
    void showErrors();
    [[nodiscard]] const model::DataTypeDecl *currentDecl() const;

    model::ProjectModel &m_projectModel;
    QString m_typeName;
    int m_index = -1; // where the type is in the model's list: finds it again after an undone rename
    bool m_present = true; // false once the type left the project (an undo may bring it back)
    QStringList m_otherNames; // the other POU and type names when the form was loaded
    QUndoStack *m_undoStack;
    RenameMembers m_renameMembers;
    std::vector<FormError> m_errors;

    QLineEdit *m_name;
    MessageLabel *m_nameMessage = nullptr;
    QComboBox *m_kind;
    QStackedWidget *m_stack;
    std::array<KindPage *, 6> m_pages {};
    QLineEdit *m_initialValue;
    MessageLabel *m_initialValueMessage = nullptr;
    QLabel *m_previewLabel;
    QPlainTextEdit *m_preview;
};

} // namespace iec::editors
