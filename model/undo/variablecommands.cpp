#include "model/undo/variablecommands.h"

#include <QCoreApplication>

#include <algorithm>

namespace iec::model {

namespace {

std::optional<Interface> interfaceOf(const ProjectModel &model, PouId pou)
{
    const Pou *found = model.project().findPou(pou);
    return found ? found->pouInterface : std::nullopt;
}

} // namespace

AddVariableCommand::AddVariableCommand(
    ProjectModel &model, PouId pou, VarListKind kind, Variable variable, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_pou(pou)
    , m_kind(kind)
    , m_variable(std::move(variable))
    , m_before(interfaceOf(model, pou))
{
    setText(QCoreApplication::translate("iec::model::AddVariableCommand", "Add variable %1").arg(m_variable.name));
}

AddVariableCommand *AddVariableCommand::duplicate(
    ProjectModel &model, PouId pou, const QString &name, const QString &newName)
{
    Variable copy;
    VarListKind kind = VarListKind::Local;
    if (const Pou *found = model.project().findPou(pou); found && found->pouInterface) {
        for (const VarList &list : found->pouInterface->varLists) {
            const auto it = std::ranges::find_if(
                list.variables, [&](const Variable &v) { return v.name.compare(name, Qt::CaseInsensitive) == 0; });
            if (it != list.variables.end()) {
                copy = *it;
                kind = list.kind;
                break;
            }
        }
    }
    copy.name = newName;
    copy.globalId.reset();
    return new AddVariableCommand(model, pou, kind, std::move(copy));
}

void AddVariableCommand::redo()
{
    m_model.addVariable(m_pou, m_kind, m_variable);
}

void AddVariableCommand::undo()
{
    m_model.setInterface(m_pou, m_before);
}

RemoveVariableCommand::RemoveVariableCommand(ProjectModel &model, PouId pou, QString name, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_pou(pou)
    , m_name(std::move(name))
    , m_before(interfaceOf(model, pou))
{
    setText(QCoreApplication::translate("iec::model::RemoveVariableCommand", "Delete variable %1").arg(m_name));
}

void RemoveVariableCommand::redo()
{
    m_model.removeVariable(m_pou, m_name);
}

void RemoveVariableCommand::undo()
{
    m_model.setInterface(m_pou, m_before);
}

ChangeVariableCommand::ChangeVariableCommand(
    ProjectModel &model, PouId pou, const QString &name, Variable variable, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_pou(pou)
    , m_after(std::move(variable))
{
    if (const Variable *before = model.findVariable(pou, name))
        m_before = *before;
    setText(QCoreApplication::translate("iec::model::ChangeVariableCommand", "Change variable %1").arg(name));
}

ChangeVariableCommand *ChangeVariableCommand::rename(
    ProjectModel &model, PouId pou, const QString &name, const QString &newName)
{
    Variable renamed;
    if (const Variable *variable = model.findVariable(pou, name))
        renamed = *variable;
    renamed.name = newName;
    return new ChangeVariableCommand(model, pou, name, std::move(renamed));
}

void ChangeVariableCommand::redo()
{
    m_model.changeVariable(m_pou, m_before.name, m_after);
}

void ChangeVariableCommand::undo()
{
    m_model.changeVariable(m_pou, m_after.name, m_before);
}

namespace {

int variableFields(const Variable &before, const Variable &after)
{
    return model::changedFields(before, after, &Variable::name, &Variable::type, &Variable::initialValue,
        &Variable::address, &Variable::documentation);
}

} // namespace

bool ChangeVariableCommand::mergeWith(const QUndoCommand *other)
{
    // Only repeated edits of one field of one variable are one step (typing a name in several
    // goes); a change of another field is a gesture of its own.
    const auto *change = static_cast<const ChangeVariableCommand *>(other);
    if (change->m_pou != m_pou || change->m_before.name != m_after.name
        || !sameSingleField(variableFields(m_before, m_after), variableFields(change->m_before, change->m_after)))
        return false;
    m_after = change->m_after;
    return true;
}

SetInterfaceCommand::SetInterfaceCommand(
    ProjectModel &model, PouId pou, std::optional<Interface> declarations, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_pou(pou)
    , m_before(interfaceOf(model, pou))
    , m_after(std::move(declarations))
{
    setText(QCoreApplication::translate("iec::model::SetInterfaceCommand", "Edit declarations"));
}

void SetInterfaceCommand::redo()
{
    m_model.setInterface(m_pou, m_after);
}

void SetInterfaceCommand::undo()
{
    m_model.setInterface(m_pou, m_before);
}

} // namespace iec::model
