#pragma once

#include "model/instances.h"
#include "model/pou.h"
#include "model/project.h"

#include <QMetaType>
#include <QString>

#include <optional>
#include <vector>

// Global variable lists as the IDE shows them, without widgets: finding, reading and replacing a
// list's declarations, and the list operations of the project tree (add, rename, duplicate,
// delete) as functions from configurations to configurations, which the app wraps in one
// SetInstancesCommand each.
namespace iec::editors {

// One global variable list: the VAR_GLOBAL lists of a configuration or of one of its resources
// that share a name. CODESYS writes a list's CONSTANT and RETAIN sections as separate
// globalVars elements with the list's name, and code may say `List.Variable`; the unnamed lists
// of an owner (IEC text, Beremiz) form one list shown under the owner's name.
struct GlobalListRef {
    QString configuration;
    QString resource; // empty: the configuration's own VAR_GLOBAL lists
    QString name;     // the list's name; empty: the owner's unnamed lists

    // The name the tree and the tab show: the list's name, else its owner's.
    [[nodiscard]] QString displayName() const;
    // A key that stays the same while the list keeps its name and owner (case-insensitive).
    [[nodiscard]] QString key() const;
    [[nodiscard]] bool sameList(const GlobalListRef &other) const { return key() == other.key(); }
    bool operator==(const GlobalListRef &) const = default;
};

// Every list of the project, in the order of the file (configurations, then their resources).
[[nodiscard]] std::vector<GlobalListRef> globalLists(const model::Instances &instances);
[[nodiscard]] bool globalListExists(const model::Instances &instances, const GlobalListRef &list);
// The list's var lists, as an interface so the declaration editor's pieces read and write them.
[[nodiscard]] model::Interface globalListDeclarations(const model::Instances &instances, const GlobalListRef &list);
// The instances with the list's var lists replaced by `declarations` (each named like the list,
// kept where the first one was). nullopt when the list does not exist.
[[nodiscard]] std::optional<model::Instances> withGlobalListDeclarations(
    const model::Instances &instances, const GlobalListRef &list, const model::Interface &declarations);

// Where a new list goes: the first resource of the first configuration (CODESYS keeps global
// lists per PLC), or the configuration itself when it has no resource.
[[nodiscard]] std::optional<GlobalListRef> defaultGlobalListOwner(const model::Instances &instances);

// The program a project without a configuration runs (as the compiler picks it): the only
// PROGRAM, else PLC_PRG or Main, else the first; empty when there is none.
[[nodiscard]] QString implicitProgram(const model::Project &project);

// A project without a configuration runs its main program in an implicit cyclic task. Global
// lists and tasks need a configuration, so this makes the implicit one explicit: configuration
// "Config", resource "Resource", cyclic task "MainTask" every `interval` running `program`
// (no instance when `program` is empty). Unchanged when there is a configuration.
[[nodiscard]] model::Instances withExplicitConfiguration(
    const model::Instances &instances, const QString &program, const QString &interval = QStringLiteral("T#10ms"));

// The list operations. Each returns the changed instances and the list they made or renamed;
// nullopt when the list does not exist (or, for add, the owner does not).
struct GlobalListEdit {
    model::Instances instances;
    GlobalListRef list;
};
// An empty VAR_GLOBAL list named `name` in the owner of `owner` (its configuration and resource).
[[nodiscard]] std::optional<GlobalListEdit> withGlobalListAdded(
    const model::Instances &instances, const GlobalListRef &owner, const QString &name);
[[nodiscard]] std::optional<GlobalListEdit> withGlobalListRenamed(
    const model::Instances &instances, const GlobalListRef &list, const QString &newName);
// The copy follows the list and declares the same variables; the compiler will say that they are
// declared twice until the user renames them, as CODESYS does.
[[nodiscard]] std::optional<GlobalListEdit> withGlobalListDuplicated(
    const model::Instances &instances, const GlobalListRef &list, const QString &copyName);
[[nodiscard]] std::optional<model::Instances> withGlobalListRemoved(
    const model::Instances &instances, const GlobalListRef &list);

// The list that declares global `variable` in configuration `configuration` other than `except`;
// nullopt when none does. Globals of a configuration share one namespace.
[[nodiscard]] std::optional<GlobalListRef> otherListDeclaring(const model::Instances &instances,
    const QString &configuration, const QString &variable, const GlobalListRef &except);

// The first list that declares global `variable` (in any configuration); with `listName`, only a
// list of that name (CODESYS's `List.Variable`). nullopt when none does.
[[nodiscard]] std::optional<GlobalListRef> globalListDeclaring(
    const model::Instances &instances, const QString &variable, const QString &listName = {});

} // namespace iec::editors

Q_DECLARE_METATYPE(iec::editors::GlobalListRef)
