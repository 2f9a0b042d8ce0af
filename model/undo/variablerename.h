#pragma once

#include "model/instances.h"
#include "model/pou.h"

#include <QString>

#include <optional>
#include <vector>

// What a rename of variables (or struct members) is, found by comparing declarations before and
// after a gesture. The reference updates themselves need the lexer and live in the app
// (app/referencerename); these functions only know the model.
namespace iec::model {

struct VariableRename {
    QString oldName;
    QString newName;

    bool operator==(const VariableRename &) const = default;
};

// The variables that `after` renames compared with `before`. A rename is a variable that keeps
// its place (the same var lists of the same kinds, the same number of variables in each) under
// another name; its type and value may change with it. When the lists differ in shape (a variable
// added, removed or moved) nothing is a rename and the result is empty. A change of case only is
// a rename too (uses are respelled).
[[nodiscard]] std::vector<VariableRename> renamedVariables(
    const std::vector<VarList> &before, const std::vector<VarList> &after);
[[nodiscard]] std::vector<VariableRename> renamedVariables(
    const std::optional<Interface> &before, const std::optional<Interface> &after);
// The members a struct type renames, by the same rule (empty unless both are structs).
[[nodiscard]] std::vector<VariableRename> renamedMembers(const DataType &before, const DataType &after);

// Where a global variable is declared: configuration `configuration`, and resource `resource`
// of it (-1: the configuration's own VAR_GLOBAL lists).
struct GlobalLocation {
    int configuration = -1;
    int resource = -1;

    [[nodiscard]] bool isValid() const { return configuration >= 0; }
    bool operator==(const GlobalLocation &) const = default;
};

// The first place that declares global `name` (case-insensitive); invalid when none does.
[[nodiscard]] GlobalLocation findGlobal(const Instances &instances, const QString &name);
[[nodiscard]] const Variable *findGlobalVariable(const Instances &instances, const QString &name);

// The instances with global `oldName` renamed where `findGlobal` finds it, and every task whose
// SINGLE input names it; nullopt when no global has that name.
[[nodiscard]] std::optional<Instances> instancesWithGlobalRenamed(
    const Instances &instances, const QString &oldName, const QString &newName);

} // namespace iec::model
