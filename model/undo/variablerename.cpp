#include "model/undo/variablerename.h"

namespace iec::model {

namespace {

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

bool sameShape(const std::vector<VarList> &before, const std::vector<VarList> &after)
{
    if (before.size() != after.size())
        return false;
    for (size_t i = 0; i < before.size(); ++i) {
        if (before[i].kind != after[i].kind || before[i].variables.size() != after[i].variables.size())
            return false;
    }
    return true;
}

std::vector<VariableRename> renamedAtSamePlaces(const std::vector<Variable> &before, const std::vector<Variable> &after)
{
    std::vector<VariableRename> renames;
    for (size_t i = 0; i < before.size() && i < after.size(); ++i) {
        if (before[i].name != after[i].name)
            renames.push_back({before[i].name, after[i].name});
    }
    return renames;
}

} // namespace

std::vector<VariableRename> renamedVariables(const std::vector<VarList> &before, const std::vector<VarList> &after)
{
    if (!sameShape(before, after))
        return {};
    std::vector<VariableRename> renames;
    for (size_t i = 0; i < before.size(); ++i) {
        for (VariableRename &rename : renamedAtSamePlaces(before[i].variables, after[i].variables))
            renames.push_back(std::move(rename));
    }
    return renames;
}

std::vector<VariableRename> renamedVariables(const std::optional<Interface> &before, const std::optional<Interface> &after)
{
    static const std::vector<VarList> none;
    return renamedVariables(before ? before->varLists : none, after ? after->varLists : none);
}

std::vector<VariableRename> renamedMembers(const DataType &before, const DataType &after)
{
    const auto *oldStruct = std::get_if<StructType>(&before.kind);
    const auto *newStruct = std::get_if<StructType>(&after.kind);
    if (!oldStruct || !newStruct || oldStruct->members.size() != newStruct->members.size())
        return {};
    return renamedAtSamePlaces(oldStruct->members, newStruct->members);
}

namespace {

const Variable *findIn(const std::vector<VarList> &lists, const QString &name)
{
    for (const VarList &list : lists) {
        for (const Variable &variable : list.variables) {
            if (sameName(variable.name, name))
                return &variable;
        }
    }
    return nullptr;
}

std::vector<VarList> *globalListsAt(Instances &instances, GlobalLocation at)
{
    Configuration &configuration = instances.configurations[size_t(at.configuration)];
    return at.resource < 0 ? &configuration.globalVars : &configuration.resources[size_t(at.resource)].globalVars;
}

} // namespace

GlobalLocation findGlobal(const Instances &instances, const QString &name)
{
    for (size_t c = 0; c < instances.configurations.size(); ++c) {
        const Configuration &configuration = instances.configurations[c];
        if (findIn(configuration.globalVars, name))
            return {int(c), -1};
        for (size_t r = 0; r < configuration.resources.size(); ++r) {
            if (findIn(configuration.resources[r].globalVars, name))
                return {int(c), int(r)};
        }
    }
    return {};
}

const Variable *findGlobalVariable(const Instances &instances, const QString &name)
{
    const GlobalLocation at = findGlobal(instances, name);
    if (!at.isValid())
        return nullptr;
    const Configuration &configuration = instances.configurations[size_t(at.configuration)];
    return findIn(at.resource < 0 ? configuration.globalVars : configuration.resources[size_t(at.resource)].globalVars,
        name);
}

std::optional<Instances> instancesWithGlobalRenamed(
    const Instances &instances, const QString &oldName, const QString &newName)
{
    const GlobalLocation at = findGlobal(instances, oldName);
    if (!at.isValid())
        return std::nullopt;
    Instances result = instances;
    for (VarList &list : *globalListsAt(result, at)) {
        for (Variable &variable : list.variables) {
            if (sameName(variable.name, oldName))
                variable.name = newName;
        }
    }
    // A task started by the rising edge of the global (SINGLE) names it.
    for (Configuration &configuration : result.configurations) {
        for (Resource &resource : configuration.resources) {
            for (Task &task : resource.tasks) {
                if (task.single && sameName(*task.single, oldName))
                    task.single = newName;
            }
        }
    }
    return result;
}

} // namespace iec::model
