#pragma once

#include "model/undo/modelcommand.h"

#include <vector>

namespace iec::model {

// Replaces every element of a graphical body with a new list in one step: what a structured edit
// of any graphical editor produces (an SFC command, an LD network edit, a paste, a layout). The
// command keeps the list that is not in the body (the one after before redo, the one before
// after it) and swaps it with the body's (ProjectModel::swapElements: linear time, one signal per
// kind of change, no copy of a large body), so undo restores the exact elements in their exact
// order. A command that changes nothing makes itself obsolete, and QUndoStack drops it.
class SetBodyElementsCommand : public ModelCommand
{
public:
    SetBodyElementsCommand(ProjectModel &model, BodyRef ref, std::vector<Element> after, const QString &text,
        QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    BodyRef m_ref;
    std::vector<Element> m_other; // the elements that are not in the body now
    bool m_applied = false;       // whether m_other holds the elements before the command
};

} // namespace iec::model
