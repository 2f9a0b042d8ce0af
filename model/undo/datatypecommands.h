#pragma once

#include "model/undo/modelcommand.h"

namespace iec::model {

class AddDataTypeCommand : public ModelCommand
{
public:
    AddDataTypeCommand(ProjectModel &model, DataTypeDecl type, QUndoCommand *parent = nullptr);
    // Copies data type `name` under `newName`; the copy is an ordinary type (not in vendor addData).
    static AddDataTypeCommand *duplicate(ProjectModel &model, const QString &name, const QString &newName);

    void redo() override;
    void undo() override;

private:
    DataTypeDecl m_type;
};

// Removes a data type; undo puts it back at the same place.
class RemoveDataTypeCommand : public ModelCommand
{
public:
    RemoveDataTypeCommand(ProjectModel &model, const QString &name, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    DataTypeDecl m_type;
    int m_index = -1;
};

// Replaces a data type (rename included).
class ChangeDataTypeCommand : public ModelCommand
{
public:
    ChangeDataTypeCommand(ProjectModel &model, const QString &name, DataTypeDecl type, QUndoCommand *parent = nullptr);
    static ChangeDataTypeCommand *rename(ProjectModel &model, const QString &name, const QString &newName);

    void redo() override;
    void undo() override;
    // Repeated edits of the same field of the same type (its name, its definition, its initial
    // value, its documentation) merge; an edit of another field is its own step.
    int id() const override { return ChangeDataTypeMerge; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    DataTypeDecl m_before;
    DataTypeDecl m_after;
};

} // namespace iec::model
