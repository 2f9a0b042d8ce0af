#include "model/undo/sfccommands.h"

#include <unordered_set>

namespace iec::model {

SetChartElementsCommand::SetChartElementsCommand(
    ProjectModel &model, BodyRef ref, std::vector<Element> after, const QString &text, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_ref(std::move(ref))
    , m_after(std::move(after))
{
    if (const Body *body = model.body(m_ref); body && body->elements())
        m_before = *body->elements();
    setText(text);
}

void SetChartElementsCommand::redo()
{
    apply(m_model, m_ref, m_after);
}

void SetChartElementsCommand::undo()
{
    apply(m_model, m_ref, m_before);
}

void SetChartElementsCommand::apply(ProjectModel &model, const BodyRef &ref, const std::vector<Element> &target)
{
    const Body *body = model.body(ref);
    if (!body || !body->elements())
        return;
    std::unordered_set<quint64> wanted;
    for (const Element &element : target)
        wanted.insert(header(element).localId);
    std::vector<quint64> gone;
    for (const Element &element : *body->elements()) {
        if (!wanted.contains(header(element).localId))
            gone.push_back(header(element).localId);
    }
    for (quint64 localId : gone)
        model.removeElement(ref, localId);
    // The survivors keep their relative order, so inserting the new ones at their target index in
    // increasing order reproduces `target` exactly.
    for (std::size_t index = 0; index < target.size(); ++index) {
        const Element &element = target[index];
        if (model.element(ref, header(element).localId))
            model.changeElement(ref, element);
        else
            model.insertElement(ref, element, int(index));
    }
}

} // namespace iec::model
