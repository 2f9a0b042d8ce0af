#include "model/undo/bodyelementscommand.h"

namespace iec::model {

SetBodyElementsCommand::SetBodyElementsCommand(
    ProjectModel &model, BodyRef ref, std::vector<Element> after, const QString &text, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_other(std::move(after))
{
    setText(text);
}

void SetBodyElementsCommand::redo()
{
    if (m_applied)
        return;
    m_applied = m_model.swapElements(m_ref, m_other);
    if (!m_applied)
        setObsolete(true); // nothing to undo: QUndoStack::push drops the command
}

void SetBodyElementsCommand::undo()
{
    if (m_applied && m_model.swapElements(m_ref, m_other))
        m_applied = false;
}

} // namespace iec::model
