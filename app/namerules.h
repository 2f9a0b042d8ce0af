#pragma once

#include "model/ids.h"

#include <QCoreApplication>
#include <QString>

#include <functional>
#include <optional>

namespace iec::model {
struct Project;
}

namespace iec::app {

// What a name given in the project tree must be: an IEC 61131-3 identifier (letter or '_' first,
// then letters, digits and single underscores, not ending in '_', not a keyword or elementary
// type), unique where the language needs it (case-insensitive, as IEC names are).
class NameRules
{
    Q_DECLARE_TR_FUNCTIONS(NameRules)

public:
    [[nodiscard]] static bool isIdentifier(const QString &name);

    // nullopt when `name` may name a POU; otherwise a sentence saying why not. POUs and data
    // types share one namespace. `renamed` is the POU being renamed (its own name does not clash).
    [[nodiscard]] static std::optional<QString> pouNameError(
        const model::Project &project, const QString &name, model::PouId renamed = {});
    // The same for an action or transition of `pou` (actions and transitions share a namespace).
    // `renamed` is the part's current name when it is being renamed.
    [[nodiscard]] static std::optional<QString> partNameError(
        const model::Project &project, model::PouId pou, const QString &name, const QString &renamed = {});

    // The same for a method or property of `pou` (they share a namespace).
    [[nodiscard]] static std::optional<QString> memberNameError(
        const model::Project &project, model::PouId pou, const QString &name);
    // The same for an INTERFACE (CODESYS keeps them in addData): they share the namespace of POUs
    // and data types. `renamed` is the interface's current name when it is being renamed.
    [[nodiscard]] static std::optional<QString> interfaceNameError(
        const model::Project &project, const QString &name, const QString &renamed = {});
    // The same for a global variable list: code writes `List.Variable`, so a list's name is unique
    // among the lists and no POU or data type has it. `renamedKey` is GlobalListRef::key() of
    // the list being renamed.
    [[nodiscard]] static std::optional<QString> globalListNameError(
        const model::Project &project, const QString &name, const QString &renamedKey = {});
    [[nodiscard]] static QString uniqueGlobalListName(const model::Project &project, const QString &base);

    // `base` itself when it is free, otherwise base_1, base_2, ... (for duplicates and defaults).
    [[nodiscard]] static QString uniquePouName(const model::Project &project, const QString &base);
    [[nodiscard]] static QString uniquePartName(const model::Project &project, model::PouId pou, const QString &base);
    // The one rule for generated names: `base` when `taken` says it is free, else base_1, base_2,
    // ... (a base that ends in '_' gets the number directly: A_ gives A_1, never A__1, which
    // is no IEC identifier). `taken` is asked case-insensitively by the caller's own rule.
    [[nodiscard]] static QString firstFree(const QString &base, const std::function<bool(const QString &)> &taken);

private:
    static std::optional<QString> identifierError(const QString &name);
};

} // namespace iec::app
