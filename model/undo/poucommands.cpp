#include "model/undo/poucommands.h"

#include <QCoreApplication>

namespace iec::model {

AddPouCommand::AddPouCommand(ProjectModel &model, Pou pou, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_pou(std::move(pou))
{
    setText(QCoreApplication::translate("iec::model::AddPouCommand", "Add POU %1").arg(m_pou.name));
}

void AddPouCommand::redo()
{
    // The first redo assigns the id; later redos reuse it so other commands' ids stay valid.
    m_pou.id = m_model.addPou(m_pou);
}

void AddPouCommand::undo()
{
    m_model.removePou(m_pou.id);
}

RenamePouCommand::RenamePouCommand(ProjectModel &model, PouId id, QString newName, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_pouId(id)
    , m_newName(std::move(newName))
{
    if (const Pou *pou = model.project().findPou(id))
        m_oldName = pou->name;
    setText(QCoreApplication::translate("iec::model::RenamePouCommand", "Rename %1 to %2").arg(m_oldName, m_newName));
}

void RenamePouCommand::redo()
{
    m_model.renamePou(m_pouId, m_newName);
}

void RenamePouCommand::undo()
{
    m_model.renamePou(m_pouId, m_oldName);
}

bool RenamePouCommand::mergeWith(const QUndoCommand *other)
{
    const auto *rename = static_cast<const RenamePouCommand *>(other);
    if (rename->m_pouId != m_pouId)
        return false;
    m_newName = rename->m_newName;
    return true;
}

} // namespace iec::model
