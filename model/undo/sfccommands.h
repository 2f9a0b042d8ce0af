#pragma once

#include "model/undo/modelcommand.h"

#include <vector>

namespace iec::model {

// Replaces every element of a graphical body with a new list in one step: what a structured
// SFC edit produces (new steps and transitions, rewired connections, the new layout's positions).
// The command keeps the whole list before and after and applies the difference through the
// model's element API, so undo restores the exact elements in their exact order.
// `after` must keep the surviving elements in their current relative order (new ones anywhere).
class SetChartElementsCommand : public ModelCommand
{
public:
    SetChartElementsCommand(ProjectModel &model, BodyRef ref, std::vector<Element> after, const QString &text,
        QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

    // Brings the body from its current elements to `target` (removals, changes, insertions).
    static void apply(ProjectModel &model, const BodyRef &ref, const std::vector<Element> &target);

private:
    BodyRef m_ref;
    std::vector<Element> m_before;
    std::vector<Element> m_after;
};

} // namespace iec::model
