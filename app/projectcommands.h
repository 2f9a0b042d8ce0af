#pragma once

#include "editors/common/editorlanguage.h"
#include "model/body.h"
#include "model/ids.h"
#include "model/pou.h"

#include <QCoreApplication>
#include <QString>

#include <functional>
#include <optional>

class QUndoStack;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

// What the Add POU dialog asks for.
struct NewPou {
    QString name;
    model::PouKind kind = model::PouKind::Program;
    editors::EditorLanguage language = editors::EditorLanguage::ST; // CFC: an FBD body marked as CFC
    QString returnType; // functions only: an elementary type name or a user type
};

// What the Add Action / Add Transition dialog asks for.
struct NewPouPart {
    model::BodyRef::Part part = model::BodyRef::Part::Action;
    QString name;
    editors::EditorLanguage language = editors::EditorLanguage::ST; // CFC: an FBD body marked as CFC
};

// The project tree's operations without any dialog: each checks its input, pushes one command on
// the project's undo stack and says what it did. The menus wrap them with dialogs
// (ProjectTreeActions); tests call them directly. Failures leave the model and the stack as they
// were and put a sentence into `error`.
class ProjectCommands
{
    Q_DECLARE_TR_FUNCTIONS(ProjectCommands)

public:
    ProjectCommands(model::ProjectModel &model, QUndoStack &projectStack);

    // Called before an operation reads bodies from the model: the editors push typing they still
    // hold back (a rename rewrites references, a duplicate copies the text), so none is lost.
    void setFlushPendingEdits(std::function<void()> flush) { m_flushPendingEdits = std::move(flush); }

    std::optional<model::PouId> addPou(const NewPou &pou, QString *error = nullptr);
    std::optional<model::BodyRef> addPouPart(model::PouId pou, const NewPouPart &part, QString *error = nullptr);
    // Renames a POU (updating references to it, see createRenamePouCommand) or an action/transition.
    bool rename(const model::BodyRef &item, const QString &newName, QString *error = nullptr);
    bool remove(const model::BodyRef &item);
    // Copies a POU or an action/transition under the first free name "<name>_N"; returns the copy.
    std::optional<model::BodyRef> duplicate(const model::BodyRef &item);

    // Adds an empty method or property `name` to function block `pou` (CODESYS keeps them in its
    // addData), or removes one; one step on the project's undo stack each.
    bool addMember(model::PouId pou, const QString &name, bool property, QString *error = nullptr);
    bool removeMember(model::PouId pou, const QString &name);
    // Adds an INTERFACE `name` with no methods (CODESYS keeps interfaces in the project's
    // addData), or removes one; one step on the project's undo stack each.
    bool addInterface(const QString &name, QString *error = nullptr);
    bool removeInterface(const QString &name);

    // The name an item of the tree shows for `item`; empty when it does not exist.
    [[nodiscard]] QString nameOf(const model::BodyRef &item) const;

private:
    void flushPendingEdits() const;

    model::ProjectModel &m_model;
    QUndoStack &m_stack;
    std::function<void()> m_flushPendingEdits;
};

// What a new POU, action or transition of `language` starts with: what the language's editor
// offers (SFC: an initial step "Init", a transition TRUE, a jump back), else an empty body.
[[nodiscard]] model::Body startingBody(editors::EditorLanguage language);
// The model's POU value for a new POU (its first body the startingBody, functions with their
// return type).
[[nodiscard]] model::Pou makePou(const NewPou &pou);

} // namespace iec::app
