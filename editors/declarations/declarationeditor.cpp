#include "editors/declarations/declarationeditor.h"

#include "model/projectmodel.h"
#include "model/undo/variablecommands.h"

namespace iec::editors {

DeclarationEditor::DeclarationEditor(
    model::ProjectModel &projectModel, model::PouId pou, QUndoStack &undoStack, QWidget *parent)
    : DeclarationEditorBase(undoStack, declarationClasses(), parent)
    , m_projectModel(projectModel)
    , m_pou(pou)
{
    setObjectName(QStringLiteral("declarationEditor"));
    connect(&projectModel, &model::ProjectModel::variablesChanged, this, [this](model::PouId changed) {
        if (changed == m_pou)
            refreshFromModel();
    });
    connect(&projectModel, &model::ProjectModel::projectReset, this, &DeclarationEditor::refreshFromModel);
    refreshFromModel();
}

model::Interface DeclarationEditor::declarations() const
{
    const model::Pou *pou = m_projectModel.project().findPou(m_pou);
    return pou && pou->pouInterface ? *pou->pouInterface : model::Interface {};
}

void DeclarationEditor::applyDeclarations(const model::Interface &declarations)
{
    const model::Pou *pou = m_projectModel.project().findPou(m_pou);
    if (!pou)
        return;
    // SetInterfaceCommand merges with the next one of the same POU; a parent of its own keeps
    // every gesture a separate step of the undo history.
    auto *gesture = new QUndoCommand;
    auto *command = new model::SetInterfaceCommand(m_projectModel, m_pou, declarations, gesture);
    gesture->setText(command->text());
    // A renamed variable takes its uses along, in the same undo step (as CODESYS users expect).
    const std::vector<model::VariableRename> renames = model::renamedVariables(pou->pouInterface, declarations);
    if (!renames.empty() && m_renameReferences) {
        m_renameReferences(m_pou, renames, gesture);
        gesture->setText(renames.size() == 1
                ? tr("Rename variable %1 to %2").arg(renames.front().oldName, renames.front().newName)
                : tr("Rename %n variable(s)", nullptr, int(renames.size())));
    }
    undoStack()->push(gesture);
}

} // namespace iec::editors
