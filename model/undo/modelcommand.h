#pragma once

#include "model/projectmodel.h"

#include <QUndoCommand>

namespace iec::model {

// Base of every undo command: holds the model and ids/values, never pointers into the project.
// Constructors only capture; redo() and undo() call the ProjectModel API.
class ModelCommand : public QUndoCommand
{
protected:
    ModelCommand(ProjectModel &model, QUndoCommand *parent)
        : QUndoCommand(parent)
        , m_model(model)
    { }

    ProjectModel &m_model;
};

// QUndoCommand::id() values of the commands that merge repeated edits of the same thing.
enum MergeId : int {
    RenamePouMerge = 0x1001,
    ChangeVariableMerge,
    SetBodyTextMerge,
    MoveElementsMerge,
    ChangeElementMerge,
    RenamePouPartMerge,
};

} // namespace iec::model
