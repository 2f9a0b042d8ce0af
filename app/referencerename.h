#pragma once

#include "model/ids.h"

#include <QString>

class QUndoCommand;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

// Replaces every reference to `oldName` in ST or IL text by `newName`: identifiers that match as
// a whole word, case-insensitively (IEC names are), found with the shared lexer so that comments,
// strings and pragmas stay untouched; a member after '.' (Timer.Q) is another name and is kept.
[[nodiscard]] QString renameIdentifier(const QString &text, const QString &oldName, const QString &newName);

// One undo step that renames a POU and updates what refers to it: the ST and IL bodies of every
// POU, action and transition, the LD/FBD blocks that call it, and the variables declared with the
// POU as their type (instances of a function block). Returns a parent command whose children are
// the model's own commands.
[[nodiscard]] QUndoCommand *createRenamePouCommand(
    model::ProjectModel &model, model::PouId pou, const QString &newName);

// One undo step that renames an action or a transition of `pou` and updates what refers to it in
// that POU: SFC action blocks (an action's reference), SFC transitions (a transition's condition
// reference) and calls in its ST and IL bodies.
[[nodiscard]] QUndoCommand *createRenamePouPartCommand(model::ProjectModel &model, model::PouId pou,
    model::BodyRef::Part part, const QString &oldName, const QString &newName);

} // namespace iec::app
