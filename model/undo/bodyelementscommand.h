#pragma once

#include "model/undo/modelcommand.h"

#include <vector>

namespace iec::model {

// Replaces every element of a graphical body with a new list in one step: what a structured edit
// of any graphical editor produces (an SFC command, an LD network edit, a paste, a layout). The
// command keeps the whole list before and after and applies it with
// ProjectModel::replaceElements (linear time, one signal per kind of change), so undo restores
// the exact elements in their exact order.
class SetBodyElementsCommand : public ModelCommand
{
public:
    SetBodyElementsCommand(ProjectModel &model, BodyRef ref, std::vector<Element> after, const QString &text,
        QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    BodyRef m_ref;
    std::vector<Element> m_before;
    std::vector<Element> m_after;
};

} // namespace iec::model
