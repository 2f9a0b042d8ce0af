#pragma once

#include "model/undo/modelcommand.h"

namespace iec::model {

// Adds one POU. Holds the POU value and the id it got, never a pointer into the project.
class AddPouCommand : public ModelCommand
{
public:
    AddPouCommand(ProjectModel &model, Pou pou, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

    [[nodiscard]] PouId pouId() const { return m_pou.id; }

private:
    Pou m_pou;
};

// Removes one POU; undo puts it back at the same place with the same id.
class RemovePouCommand : public ModelCommand
{
public:
    RemovePouCommand(ProjectModel &model, PouId id, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    Pou m_pou;
    int m_index = -1;
};

// Renames one POU; successive renames of the same POU merge into one undo step.
class RenamePouCommand : public ModelCommand
{
public:
    RenamePouCommand(ProjectModel &model, PouId id, QString newName, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override { return RenamePouMerge; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    PouId m_pouId;
    QString m_oldName;
    QString m_newName;
};

// Copies a POU under a new name, right after the original.
class DuplicatePouCommand : public ModelCommand
{
public:
    DuplicatePouCommand(ProjectModel &model, PouId original, QString newName, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

    [[nodiscard]] PouId copyId() const { return m_copy.id; }

private:
    PouId m_original;
    QString m_newName;
    Pou m_copy; // captured on the first redo
    int m_index = -1;
};

// Replaces a POU's addData: a method or property added or removed (CODESYS keeps them there).
class SetPouAddDataCommand : public ModelCommand
{
public:
    SetPouAddDataCommand(ProjectModel &model, PouId id, AddData addData, const QString &text, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    PouId m_pouId;
    AddData m_before;
    AddData m_after;
};

} // namespace iec::model
