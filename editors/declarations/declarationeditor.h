#pragma once

#include "editors/declarations/declarationeditorbase.h"

#include "model/ids.h"
#include "model/undo/variablerename.h"

#include <functional>

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {

// The declarations of one POU, above its body as in CODESYS (DeclarationEditorBase): every valid
// gesture is one SetInterfaceCommand on the POU's `undoStack`; a gesture that renames variables
// takes their uses along in the same step. Changes from elsewhere (undo, a rename) refresh both
// views.
class DeclarationEditor : public DeclarationEditorBase
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

protected:
    [[nodiscard]] model::Interface declarations() const override;
    void applyDeclarations(const model::Interface &declarations) override;

private:
    model::ProjectModel &m_projectModel;
    model::PouId m_pou;
    RenameReferences m_renameReferences;
};

} // namespace iec::editors
