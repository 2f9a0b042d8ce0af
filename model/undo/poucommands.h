#pragma once

#include "model/projectmodel.h"

#include <QUndoCommand>

namespace iec::model {

// Adds one POU. Holds the POU value and the id it got, never a pointer into the project.
class AddPouCommand : public QUndoCommand
{
public:
    AddPouCommand(ProjectModel &model, Pou pou, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

    [[nodiscard]] PouId pouId() const { return m_pou.id; }

private:
    ProjectModel &m_model;
    Pou m_pou;
};

// Renames one POU; successive renames of the same POU merge into one undo step.
class RenamePouCommand : public QUndoCommand
{
public:
    RenamePouCommand(ProjectModel &model, PouId id, QString newName, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override { return MergeId; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    static constexpr int MergeId = 0x1001;
    ProjectModel &m_model;
    PouId m_pouId;
    QString m_oldName;
    QString m_newName;
};

} // namespace iec::model
