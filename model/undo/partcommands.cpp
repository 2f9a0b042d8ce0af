#include "model/undo/partcommands.h"

#include <QCoreApplication>

namespace iec::model {

namespace {

QString addText(BodyRef::Part part, const QString &name)
{
    return part == BodyRef::Part::Action
        ? QCoreApplication::translate("iec::model::AddPouPartCommand", "Add action %1").arg(name)
        : QCoreApplication::translate("iec::model::AddPouPartCommand", "Add transition %1").arg(name);
}

QString removeText(BodyRef::Part part, const QString &name)
{
    return part == BodyRef::Part::Action
        ? QCoreApplication::translate("iec::model::RemovePouPartCommand", "Delete action %1").arg(name)
        : QCoreApplication::translate("iec::model::RemovePouPartCommand", "Delete transition %1").arg(name);
}

QString renameText(const QString &from, const QString &to)
{
    return QCoreApplication::translate("iec::model::RenamePouPartCommand", "Rename %1 to %2").arg(from, to);
}

} // namespace

AddPouPartCommand::AddPouPartCommand(
    ProjectModel &model, PouId pou, BodyRef::Part part, PouPart value, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_pou(pou)
    , m_part(part)
    , m_value(std::move(value))
{
    setText(addText(m_part, m_value.name));
}

AddPouPartCommand *AddPouPartCommand::duplicate(
    ProjectModel &model, PouId pou, BodyRef::Part part, const QString &name, const QString &newName)
{
    PouPart copy;
    if (const PouPart *original = model.findPouPart(pou, part, name))
        copy = *original;
    copy.name = newName;
    copy.globalId.reset(); // xsd:ID values must stay unique
    return new AddPouPartCommand(model, pou, part, std::move(copy));
}

void AddPouPartCommand::redo()
{
    m_model.addPouPart(m_pou, m_part, m_value);
}

void AddPouPartCommand::undo()
{
    m_model.removePouPart(m_pou, m_part, m_value.name);
}

RemovePouPartCommand::RemovePouPartCommand(
    ProjectModel &model, PouId pou, BodyRef::Part part, QString name, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_pou(pou)
    , m_part(part)
    , m_name(std::move(name))
    , m_index(model.pouPartIndex(pou, part, m_name))
{
    if (const PouPart *value = model.findPouPart(pou, part, m_name))
        m_value = *value;
    setText(removeText(m_part, m_name));
}

void RemovePouPartCommand::redo()
{
    m_model.removePouPart(m_pou, m_part, m_name);
}

void RemovePouPartCommand::undo()
{
    m_model.addPouPart(m_pou, m_part, m_value, m_index);
}

RenamePouPartCommand::RenamePouPartCommand(
    ProjectModel &model, PouId pou, BodyRef::Part part, QString name, QString newName, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_pou(pou)
    , m_part(part)
    , m_oldName(std::move(name))
    , m_newName(std::move(newName))
{
    setText(renameText(m_oldName, m_newName));
}

void RenamePouPartCommand::redo()
{
    m_model.renamePouPart(m_pou, m_part, m_oldName, m_newName);
}

void RenamePouPartCommand::undo()
{
    m_model.renamePouPart(m_pou, m_part, m_newName, m_oldName);
}

bool RenamePouPartCommand::mergeWith(const QUndoCommand *other)
{
    const auto *rename = static_cast<const RenamePouPartCommand *>(other);
    if (rename->m_pou != m_pou || rename->m_part != m_part || rename->m_oldName != m_newName)
        return false;
    m_newName = rename->m_newName;
    setText(renameText(m_oldName, m_newName));
    return true;
}

} // namespace iec::model
