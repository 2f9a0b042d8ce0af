#include "model/undo/poucommands.h"

#include <QCoreApplication>

namespace iec::model {

AddPouCommand::AddPouCommand(ProjectModel &model, Pou pou, QUndoCommand *parent)
    : ModelCommand(model, parent)
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

RemovePouCommand::RemovePouCommand(ProjectModel &model, PouId id, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_index(model.pouIndex(id))
{
    if (const Pou *pou = model.project().findPou(id))
        m_pou = *pou;
    m_pou.id = id;
    setText(QCoreApplication::translate("iec::model::RemovePouCommand", "Delete POU %1").arg(m_pou.name));
}

void RemovePouCommand::redo()
{
    m_model.removePou(m_pou.id);
}

void RemovePouCommand::undo()
{
    m_model.addPou(m_pou, m_index);
}

RenamePouCommand::RenamePouCommand(ProjectModel &model, PouId id, QString newName, QUndoCommand *parent)
    : ModelCommand(model, parent)
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
    setText(QCoreApplication::translate("iec::model::RenamePouCommand", "Rename %1 to %2").arg(m_oldName, m_newName));
    return true;
}

DuplicatePouCommand::DuplicatePouCommand(ProjectModel &model, PouId original, QString newName, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_original(original)
    , m_newName(std::move(newName))
{
    setText(QCoreApplication::translate("iec::model::DuplicatePouCommand", "Duplicate POU as %1").arg(m_newName));
}

void DuplicatePouCommand::redo()
{
    // The model makes the copy once; later redos put back that same copy with the same id.
    if (!m_copy.id.isValid()) {
        if (const Pou *copy = m_model.project().findPou(m_model.duplicatePou(m_original, m_newName))) {
            m_copy = *copy;
            m_index = m_model.pouIndex(copy->id);
        }
    } else {
        m_model.addPou(m_copy, m_index);
    }
}

void DuplicatePouCommand::undo()
{
    m_model.removePou(m_copy.id);
}

SetPouAddDataCommand::SetPouAddDataCommand(
    ProjectModel &model, PouId id, AddData addData, const QString &text, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_pouId(id)
    , m_after(std::move(addData))
{
    if (const Pou *pou = model.project().findPou(id))
        m_before = pou->addData;
    setText(text);
    setObsolete(m_before == m_after);
}

void SetPouAddDataCommand::redo()
{
    m_model.setPouAddData(m_pouId, m_after);
}

void SetPouAddDataCommand::undo()
{
    m_model.setPouAddData(m_pouId, m_before);
}

} // namespace iec::model
