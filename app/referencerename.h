#pragma once

#include "app/textrename.h"
#include "model/ids.h"
#include "model/project.h"
#include "model/undo/variablerename.h"

#include <QString>

#include <vector>

class QUndoCommand;

namespace iec::model {
class ProjectModel;
}

// Renames that reach every reference: one undo step per gesture, made of the model's own commands
// (a parent QUndoCommand whose children change the declaration, the text bodies, the graphical
// elements and the configurations). Every rewrite of text goes through the shared lexer
// (app/textrename.h), so comments, strings and pragmas never change.
namespace iec::app {

// One undo step that renames a POU and updates what refers to it: the ST and IL bodies of every
// POU, action and transition, the LD/FBD blocks that call it, the variables declared with the
// POU as their type (instances of a function block) and the tasks that run it.
[[nodiscard]] QUndoCommand *createRenamePouCommand(
    model::ProjectModel &model, model::PouId pou, const QString &newName);

// One undo step that renames an action or a transition of `pou` and updates what refers to it in
// that POU: SFC action blocks (an action's reference), SFC transitions (a transition's condition
// reference) and calls in its ST and IL bodies.
[[nodiscard]] QUndoCommand *createRenamePouPartCommand(model::ProjectModel &model, model::PouId pou,
    model::BodyRef::Part part, const QString &oldName, const QString &newName);

// Adds to `gesture` what a rename of variables of `pou` changes besides the declarations (which
// the caller changes): every use in the POU's bodies, actions and transitions (text, LD/FBD
// variables, contacts, coils, block instances, SFC conditions, action qualifiers' indicators and
// action blocks that name the variable); for the inputs and outputs of a function block or
// function, `instance.Input`, `instance(Input := ...)` and the block pins in every POU. Call it
// before the declarations change (it reads them to know the types).
void addVariableReferenceRenames(
    model::ProjectModel &model, model::PouId pou, const Renames &renames, QUndoCommand *gesture);

// One undo step: variable `oldName` of `pou` is called `newName`, and every use follows.
[[nodiscard]] QUndoCommand *createRenameVariableCommand(
    model::ProjectModel &model, model::PouId pou, const QString &oldName, const QString &newName);

// Adds to `gesture` what a rename of global variables changes besides the configurations (the
// VAR_GLOBAL lists and task SINGLE inputs, see model::instancesWithGlobalRenamed): the
// VAR_EXTERNAL declarations and the uses in every POU that sees the global (one that declares a
// local of the same name does not; CODESYS lets a POU read a global without VAR_EXTERNAL).
void addGlobalReferenceRenames(model::ProjectModel &model, const Renames &renames, QUndoCommand *gesture);

// One undo step: global `oldName` (the first one model::findGlobal finds, in a configuration or
// a resource) is called `newName`, and every use follows. Empty (no children) when there is no
// such global.
[[nodiscard]] QUndoCommand *createRenameGlobalVariableCommand(
    model::ProjectModel &model, const QString &oldName, const QString &newName);

// Adds to `gesture` the updates for members of struct type `typeName` renamed: `x.Member` and
// `a[i].Member` wherever the declarations say x is of that type, and the member names in the
// initial values of POU variables (`(Member := 1)`). Call it before the type changes.
void addMemberReferenceRenames(
    model::ProjectModel &model, const QString &typeName, const Renames &renames, QUndoCommand *gesture);

// One undo step: member `oldName` of struct type `typeName` is called `newName`, uses follow.
[[nodiscard]] QUndoCommand *createRenameMemberCommand(
    model::ProjectModel &model, const QString &typeName, const QString &oldName, const QString &newName);

// The project value with POUs and data types renamed (several at once, as `renames` says) and
// every reference inside it following: ST/IL bodies, LD/FBD blocks, the types of variables,
// members, array elements and return types, and the program instances of tasks. Import uses it
// before the imported names join the open project.
[[nodiscard]] model::Project projectWithTypesRenamed(const model::Project &project, const Renames &renames);

} // namespace iec::app
