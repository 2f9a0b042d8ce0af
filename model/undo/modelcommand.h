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
    ChangeDataTypeMerge,
};

// Which fields of a value a change touches: one bit per member pointer given, in that order, and
// the next bit when anything else changed as well. Commands use it to merge only repeated edits
// of one field (sameSingleField).
template <typename T, typename... Members>
int changedFields(const T &before, const T &after, Members... members)
{
    T rest = after;
    int fields = 0;
    int bit = 1;
    const auto compare = [&](auto member) {
        if (!(before.*member == after.*member)) {
            fields |= bit;
            rest.*member = before.*member;
        }
        bit <<= 1;
    };
    (compare(members), ...);
    return rest == before ? fields : fields | bit;
}

// Two changes that each touch the same one field.
inline bool sameSingleField(int fields, int otherFields)
{
    return fields == otherFields && fields != 0 && (fields & (fields - 1)) == 0;
}

} // namespace iec::model
