#pragma once

#include "model/undo/modelcommand.h"

namespace iec::model {

// Adds an action or a transition (BodyRef::Part) with its body to a POU.
class AddPouPartCommand : public ModelCommand
{
public:
    AddPouPartCommand(
        ProjectModel &model, PouId pou, BodyRef::Part part, PouPart value, QUndoCommand *parent = nullptr);
    // Copies action/transition `name` (body, documentation, addData) under `newName`, at the end.
    static AddPouPartCommand *duplicate(
        ProjectModel &model, PouId pou, BodyRef::Part part, const QString &name, const QString &newName);

    void redo() override;
    void undo() override;

private:
    PouId m_pou;
    BodyRef::Part m_part;
    PouPart m_value;
};

// Removes an action or a transition; undo puts it back in place with its body.
class RemovePouPartCommand : public ModelCommand
{
public:
    RemovePouPartCommand(
        ProjectModel &model, PouId pou, BodyRef::Part part, QString name, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    PouId m_pou;
    BodyRef::Part m_part;
    QString m_name;
    PouPart m_value;
    int m_index = -1;
};

// Renames an action or a transition; successive renames of the same one merge.
class RenamePouPartCommand : public ModelCommand
{
public:
    RenamePouPartCommand(ProjectModel &model, PouId pou, BodyRef::Part part, QString name, QString newName,
        QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override { return RenamePouPartMerge; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    PouId m_pou;
    BodyRef::Part m_part;
    QString m_oldName;
    QString m_newName;
};

} // namespace iec::model
