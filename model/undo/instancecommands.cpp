#include "model/undo/instancecommands.h"

#include <QCoreApplication>

namespace iec::model {

SetInstancesCommand::SetInstancesCommand(ProjectModel &model, Instances instances, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_before(model.project().instances)
    , m_after(std::move(instances))
{
    setText(QCoreApplication::translate("iec::model::SetInstancesCommand", "Change configurations"));
}

void SetInstancesCommand::redo()
{
    m_model.setInstances(m_after);
}

void SetInstancesCommand::undo()
{
    m_model.setInstances(m_before);
}

SetProjectAddDataCommand::SetProjectAddDataCommand(ProjectModel &model, AddData addData, const QString &text, QUndoCommand *parent)
    : ModelCommand(model, parent)
    , m_before(model.project().addData)
    , m_after(std::move(addData))
{
    setText(text);
    setObsolete(m_before == m_after);
}

void SetProjectAddDataCommand::redo()
{
    m_model.setProjectAddData(m_after);
}

void SetProjectAddDataCommand::undo()
{
    m_model.setProjectAddData(m_before);
}

namespace {

bool renameIn(std::vector<PouInstance> &instances, const QString &oldName, const QString &newName)
{
    bool changed = false;
    for (PouInstance &instance : instances) {
        if (instance.typeName.compare(oldName, Qt::CaseInsensitive) == 0) {
            instance.typeName = newName;
            changed = true;
        }
    }
    return changed;
}

} // namespace

std::optional<Instances> instancesWithProgramRenamed(const Instances &instances, const QString &oldName,
    const QString &newName)
{
    Instances result = instances;
    bool changed = false;
    for (Configuration &configuration : result.configurations) {
        for (Resource &resource : configuration.resources) {
            changed |= renameIn(resource.pouInstances, oldName, newName);
            for (Task &task : resource.tasks)
                changed |= renameIn(task.pouInstances, oldName, newName);
        }
    }
    if (!changed)
        return std::nullopt;
    return result;
}

} // namespace iec::model
