#pragma once

#include "model/datatypes.h"
#include "model/opaque.h"
#include "model/values.h"

#include <QString>

#include <optional>
#include <vector>

namespace iec::model {

// One entry of a ppx:varListPlain: a variable or a struct member.
struct Variable {
    QString name;
    std::optional<QString> address; // AT %IX0.0
    std::optional<QString> globalId;
    DataType type;
    std::optional<Value> initialValue;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const Variable &) const = default;
};

inline bool StructType::operator==(const StructType &other) const
{
    return members == other.members && addData == other.addData && documentation == other.documentation
        && extras == other.extras;
}

// The element a var list is written as inside a POU interface (or a configuration / resource).
enum class VarListKind { Local, Temp, Input, Output, InOut, External, Global, Access };

// ppx:varList.
struct VarList {
    VarListKind kind = VarListKind::Local;
    std::optional<QString> name;
    bool constant = false;
    bool retain = false;
    bool nonretain = false;
    bool persistent = false;
    bool nonpersistent = false;
    std::vector<Variable> variables;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const VarList &) const = default;
};

enum class AccessDirection { ReadOnly, ReadWrite };

// ppx:varListAccess / accessVariable.
struct AccessVariable {
    QString alias;
    QString instancePathAndName;
    std::optional<AccessDirection> direction;
    DataType type;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const AccessVariable &) const = default;
};

struct AccessVarList {
    std::vector<AccessVariable> variables;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const AccessVarList &) const = default;
};

// ppx:varListConfig / configVariable.
struct ConfigVariable {
    QString instancePathAndName;
    std::optional<QString> address;
    DataType type;
    std::optional<Value> initialValue;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const ConfigVariable &) const = default;
};

struct ConfigVarList {
    std::vector<ConfigVariable> variables;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const ConfigVarList &) const = default;
};

} // namespace iec::model
