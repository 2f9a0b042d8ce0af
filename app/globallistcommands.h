#pragma once

#include "editors/globals/globallists.h"

#include <QCoreApplication>

#include <optional>

class QUndoStack;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

// The project tree's operations on global variable lists, without dialogs (as ProjectCommands
// for POUs): each checks its input, pushes one SetInstancesCommand on the project's undo stack
// and returns the list it made; failures change nothing and say why in `error`.
class GlobalListCommands
{
    Q_DECLARE_TR_FUNCTIONS(GlobalListCommands)

public:
    GlobalListCommands(model::ProjectModel &model, QUndoStack &projectStack);

    // A new empty list in `owner` (its configuration and resource), by default where
    // editors::defaultGlobalListOwner puts it. A project without a configuration gets one first
    // (editors::withExplicitConfiguration), in the same undo step, so it runs as before.
    std::optional<editors::GlobalListRef> add(const QString &name, QString *error = nullptr,
        const std::optional<editors::GlobalListRef> &owner = std::nullopt);
    // Renames the list; uses written `Old.Variable` in the code are not rewritten (Find in
    // Project finds them), as CODESYS leaves them.
    std::optional<editors::GlobalListRef> rename(
        const editors::GlobalListRef &list, const QString &newName, QString *error = nullptr);
    // A copy under the first free name "<name>_N".
    std::optional<editors::GlobalListRef> duplicate(const editors::GlobalListRef &list);
    bool remove(const editors::GlobalListRef &list);
    // The configuration the task configuration shows: the first one. A project without one gets
    // the one it ran implicitly (editors::withExplicitConfiguration) in one undo step, so its
    // tasks can be edited as CODESYS's task configuration always can.
    QString taskConfiguration();

private:
    model::ProjectModel &m_model;
    QUndoStack &m_stack;
};

} // namespace iec::app
