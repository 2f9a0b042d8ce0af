#include "app/globallistcommands.h"

#include "app/namerules.h"
#include "model/projectmodel.h"
#include "model/undo/instancecommands.h"

#include <QUndoStack>

namespace iec::app {

using editors::GlobalListRef;

namespace {

std::optional<GlobalListRef> fail(QString *error, const QString &message)
{
    if (error)
        *error = message;
    return std::nullopt;
}

} // namespace

GlobalListCommands::GlobalListCommands(model::ProjectModel &model, QUndoStack &projectStack)
    : m_model(model)
    , m_stack(projectStack)
{
}

std::optional<GlobalListRef> GlobalListCommands::add(
    const QString &name, QString *error, const std::optional<GlobalListRef> &owner)
{
    const model::Project &project = m_model.project();
    if (const auto problem = NameRules::globalListNameError(project, name))
        return fail(error, *problem);
    const model::Instances configured
        = editors::withExplicitConfiguration(project.instances, editors::implicitProgram(project));
    const std::optional<GlobalListRef> where = owner ? owner : editors::defaultGlobalListOwner(configured);
    auto added = where ? editors::withGlobalListAdded(configured, *where, name) : std::nullopt;
    if (!added)
        return fail(error, tr("The configuration or resource for the list does not exist any more."));
    auto *command = new model::SetInstancesCommand(m_model, std::move(added->instances));
    command->setText(tr("Add global variable list %1").arg(name));
    m_stack.push(command);
    return added->list;
}

std::optional<GlobalListRef> GlobalListCommands::rename(const GlobalListRef &list, const QString &newName, QString *error)
{
    if (newName == list.name)
        return list;
    if (const auto problem = NameRules::globalListNameError(m_model.project(), newName, list.key()))
        return fail(error, *problem);
    auto renamed = editors::withGlobalListRenamed(m_model.project().instances, list, newName);
    if (!renamed)
        return fail(error, tr("The list does not exist any more."));
    auto *command = new model::SetInstancesCommand(m_model, std::move(renamed->instances));
    command->setText(tr("Rename global variable list %1 to %2").arg(list.displayName(), newName));
    m_stack.push(command);
    return renamed->list;
}

std::optional<GlobalListRef> GlobalListCommands::duplicate(const GlobalListRef &list)
{
    const QString copyName = NameRules::uniqueGlobalListName(m_model.project(), list.displayName());
    auto copy = editors::withGlobalListDuplicated(m_model.project().instances, list, copyName);
    if (!copy)
        return std::nullopt;
    auto *command = new model::SetInstancesCommand(m_model, std::move(copy->instances));
    command->setText(tr("Duplicate global variable list %1").arg(list.displayName()));
    m_stack.push(command);
    return copy->list;
}

bool GlobalListCommands::remove(const GlobalListRef &list)
{
    auto removed = editors::withGlobalListRemoved(m_model.project().instances, list);
    if (!removed)
        return false;
    auto *command = new model::SetInstancesCommand(m_model, std::move(*removed));
    command->setText(tr("Delete global variable list %1").arg(list.displayName()));
    m_stack.push(command);
    return true;
}

QString GlobalListCommands::taskConfiguration()
{
    const model::Project &project = m_model.project();
    if (!project.instances.configurations.empty())
        return project.instances.configurations.front().name;
    model::Instances configured = editors::withExplicitConfiguration(project.instances, editors::implicitProgram(project));
    const QString name = configured.configurations.front().name;
    auto *command = new model::SetInstancesCommand(m_model, std::move(configured));
    command->setText(tr("Create task configuration %1").arg(name));
    m_stack.push(command);
    return name;
}

} // namespace iec::app
