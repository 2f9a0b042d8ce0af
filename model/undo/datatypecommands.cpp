#include "model/undo/datatypecommands.h"

#include <QCoreApplication>

namespace iec::model {

AddDataTypeCommand::AddDataTypeCommand(ProjectModel &model, DataTypeDecl type, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_type(std::move(type))
{
    setText(QCoreApplication::translate("iec::model::AddDataTypeCommand", "Add data type %1").arg(m_type.name));
}

AddDataTypeCommand *AddDataTypeCommand::duplicate(ProjectModel &model, const QString &name, const QString &newName)
{
    DataTypeDecl copy;
    if (const DataTypeDecl *original = model.project().findDataType(name))
        copy = *original;
    copy.name = newName;
    copy.addDataSlot = 0;
    return new AddDataTypeCommand(model, std::move(copy));
}

void AddDataTypeCommand::redo()
{
    m_model.addDataType(m_type);
}

void AddDataTypeCommand::undo()
{
    m_model.removeDataType(m_type.name);
}

RemoveDataTypeCommand::RemoveDataTypeCommand(ProjectModel &model, const QString &name, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_index(model.dataTypeIndex(name))
{
    if (const DataTypeDecl *type = model.project().findDataType(name))
        m_type = *type;
    setText(QCoreApplication::translate("iec::model::RemoveDataTypeCommand", "Delete data type %1").arg(name));
}

void RemoveDataTypeCommand::redo()
{
    m_model.removeDataType(m_type.name);
}

void RemoveDataTypeCommand::undo()
{
    m_model.addDataType(m_type, m_index);
}

ChangeDataTypeCommand::ChangeDataTypeCommand(
    ProjectModel &model, const QString &name, DataTypeDecl type, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_after(std::move(type))
{
    if (const DataTypeDecl *before = model.project().findDataType(name))
        m_before = *before;
    setText(m_before.name == m_after.name
            ? QCoreApplication::translate("iec::model::ChangeDataTypeCommand", "Change data type %1").arg(name)
            : QCoreApplication::translate("iec::model::ChangeDataTypeCommand", "Rename %1 to %2")
                  .arg(m_before.name, m_after.name));
}

ChangeDataTypeCommand *ChangeDataTypeCommand::rename(ProjectModel &model, const QString &name, const QString &newName)
{
    DataTypeDecl type;
    if (const DataTypeDecl *existing = model.project().findDataType(name))
        type = *existing;
    type.name = newName;
    return new ChangeDataTypeCommand(model, name, std::move(type));
}

void ChangeDataTypeCommand::redo()
{
    m_model.changeDataType(m_before.name, m_after);
}

void ChangeDataTypeCommand::undo()
{
    m_model.changeDataType(m_after.name, m_before);
}

namespace {

int typeFields(const DataTypeDecl &before, const DataTypeDecl &after)
{
    return model::changedFields(before, after, &DataTypeDecl::name, &DataTypeDecl::baseType,
        &DataTypeDecl::initialValue, &DataTypeDecl::documentation);
}

} // namespace

bool ChangeDataTypeCommand::mergeWith(const QUndoCommand *other)
{
    const auto *change = static_cast<const ChangeDataTypeCommand *>(other);
    if (change->m_before.name != m_after.name
        || !sameSingleField(typeFields(m_before, m_after), typeFields(change->m_before, change->m_after)))
        return false;
    m_after = change->m_after;
    setText(change->text());
    return true;
}

} // namespace iec::model
