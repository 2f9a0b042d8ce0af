#pragma once

#include "model/undo/modelcommand.h"

namespace iec::model {

// Replaces the configurations (resources, tasks, program instances) as a whole: used by a
// program rename, which must change every pouInstance that runs the program in the same step.
class SetInstancesCommand : public ModelCommand
{
public:
    SetInstancesCommand(ProjectModel &model, Instances instances, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    Instances m_before;
    Instances m_after;
};

// Replaces the project's own addData (adding or deleting a CODESYS INTERFACE kept there).
class SetProjectAddDataCommand : public ModelCommand
{
public:
    SetProjectAddDataCommand(ProjectModel &model, AddData addData, const QString &text, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    AddData m_before;
    AddData m_after;
};

// The instances with every pouInstance of type `oldName` (case-insensitive, as IEC names are)
// running `newName` instead; nullopt when nothing refers to `oldName`.
std::optional<Instances> instancesWithProgramRenamed(const Instances &instances, const QString &oldName,
    const QString &newName);

} // namespace iec::model
