#pragma once

#include "editors/declarations/declarationeditorbase.h"
#include "editors/globals/globallists.h"

#include "model/undo/variablerename.h"

#include <functional>

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {

// A global variable list (GlobalListRef) in the declaration editor's table and VAR_GLOBAL text:
// VAR_GLOBAL, VAR_GLOBAL CONSTANT and VAR_GLOBAL RETAIN sections, located variables (AT %IX0.0).
// Each valid gesture is one SetInstancesCommand on the project's `undoStack`. Besides the checks
// of every declaration editor it refuses other sections (VAR_INPUT has no place in a list) and
// names another list of the configuration declares already. A gesture that renames globals takes
// their uses along (setRenameReferences) and the tasks started by them.
//
// The editor follows its list: a rename from the tree (the list at the same place of its owner
// under a new name) retargets it; when the list is gone, listRemoved is sent.
class GlobalListEditor : public DeclarationEditorBase
{
    Q_OBJECT

public:
    GlobalListEditor(model::ProjectModel &projectModel, const GlobalListRef &list, QUndoStack &undoStack,
        QWidget *parent = nullptr);

    [[nodiscard]] const GlobalListRef &list() const { return m_list; }

    // Adds to a gesture that renames globals what else the renames change (VAR_EXTERNALs and
    // uses in the POUs); the app provides it (app/referencerename).
    using RenameReferences
        = std::function<void(const std::vector<model::VariableRename> &renames, QUndoCommand *gesture)>;
    void setRenameReferences(RenameReferences renameReferences) { m_renameReferences = std::move(renameReferences); }

    // The section keywords the class cell offers.
    [[nodiscard]] static QStringList globalClasses();

Q_SIGNALS:
    void listRenamed(const iec::editors::GlobalListRef &list);
    void listRemoved();

protected:
    [[nodiscard]] model::Interface declarations() const override;
    void applyDeclarations(const model::Interface &declarations) override;
    [[nodiscard]] QString sectionProblem(const model::VarList &list) const override;
    [[nodiscard]] QString variableProblem(const model::VarList &list, const model::Variable &variable) const override;

private:
    void followModel();

    model::ProjectModel &m_projectModel;
    GlobalListRef m_list;
    // The owner's lists when the editor last looked, to recognise a rename: the same lists but
    // for this one, under another name at its place.
    std::vector<GlobalListRef> m_ownerLists;
    RenameReferences m_renameReferences;
};

} // namespace iec::editors
