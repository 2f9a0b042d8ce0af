#pragma once

#include "model/variables.h"

#include <QString>

#include <optional>
#include <vector>

namespace iec::model {

// ppx:pouInstance: a program (or FB) instance run by a task or resource.
struct PouInstance {
    QString name;
    QString typeName;
    std::optional<QString> globalId;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const PouInstance &) const = default;
};

struct Task {
    QString name;
    std::optional<QString> single; // a variable whose rising edge starts the task
    std::optional<QString> interval; // kept as written: T#20ms, PT0.05S, 10ms
    quint32 priority = 0; // 0..65535
    std::optional<QString> globalId;
    std::vector<PouInstance> pouInstances;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const Task &) const = default;
};

struct Resource {
    QString name;
    std::optional<QString> globalId;
    std::vector<Task> tasks;
    std::vector<VarList> globalVars;
    std::vector<PouInstance> pouInstances;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const Resource &) const = default;
};

struct Configuration {
    QString name;
    std::optional<QString> globalId;
    std::vector<Resource> resources;
    std::vector<VarList> globalVars;
    std::optional<AccessVarList> accessVars;
    std::optional<ConfigVarList> configVars;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const Configuration &) const = default;
};

struct Instances {
    std::vector<Configuration> configurations;

    bool operator==(const Instances &) const = default;
};

} // namespace iec::model
