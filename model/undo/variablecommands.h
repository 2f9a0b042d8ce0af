#pragma once

#include "model/undo/modelcommand.h"

namespace iec::model {

// The variable commands restore the POU's whole interface on undo: adding may have created a var
// list and removing may leave one empty, and the interface is small.

class AddVariableCommand : public ModelCommand
{
public:
    AddVariableCommand(
        ProjectModel &model, PouId pou, VarListKind kind, Variable variable, QUndoCommand *parent = nullptr);
    // Copies variable `name` under `newName` into the first var list of the same kind.
    static AddVariableCommand *duplicate(ProjectModel &model, PouId pou, const QString &name, const QString &newName);

    void redo() override;
    void undo() override;

private:
    PouId m_pou;
    VarListKind m_kind;
    Variable m_variable;
    std::optional<Interface> m_before;
};

class RemoveVariableCommand : public ModelCommand
{
public:
    RemoveVariableCommand(ProjectModel &model, PouId pou, QString name, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    PouId m_pou;
    QString m_name;
    std::optional<Interface> m_before;
};

// Changes one variable (name, type, initial value, address, documentation...). Successive
// changes of the same field of the same variable merge; a change of another field does not.
class ChangeVariableCommand : public ModelCommand
{
public:
    ChangeVariableCommand(
        ProjectModel &model, PouId pou, const QString &name, Variable variable, QUndoCommand *parent = nullptr);
    static ChangeVariableCommand *rename(ProjectModel &model, PouId pou, const QString &name, const QString &newName);

    void redo() override;
    void undo() override;
    int id() const override { return ChangeVariableMerge; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    PouId m_pou;
    Variable m_before;
    Variable m_after;
};

// Replaces the declarations of a POU at once (the declaration editor's text was applied).
class SetInterfaceCommand : public ModelCommand
{
public:
    SetInterfaceCommand(
        ProjectModel &model, PouId pou, std::optional<Interface> declarations, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    // No merging: each application of the declaration text is one gesture, one undo step.

private:
    PouId m_pou;
    std::optional<Interface> m_before;
    std::optional<Interface> m_after;
};

} // namespace iec::model
