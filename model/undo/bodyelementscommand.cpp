#include "model/undo/bodyelementscommand.h"

namespace iec::model {

SetBodyElementsCommand::SetBodyElementsCommand(
    ProjectModel &model, BodyRef ref, std::vector<Element> after, const QString &text, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_after(std::move(after))
{
    if (const Body *body = model.body(m_ref); body && body->elements())
        m_before = *body->elements();
    setText(text);
}

void SetBodyElementsCommand::redo()
{
    m_model.replaceElements(m_ref, m_after);
}

void SetBodyElementsCommand::undo()
{
    m_model.replaceElements(m_ref, m_before);
}

} // namespace iec::model
