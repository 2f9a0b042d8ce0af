#include "editors/globals/globallists.h"

#include <algorithm>
#include <functional>

namespace iec::editors {

using model::Configuration;
using model::Instances;
using model::VarList;

namespace {

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

const Configuration *findConfiguration(const Instances &instances, const QString &name)
{
    const auto it = std::ranges::find_if(
        instances.configurations, [&](const Configuration &c) { return sameName(c.name, name); });
    return it == instances.configurations.end() ? nullptr : &*it;
}

// The VAR_GLOBAL lists of the list's owner (a configuration or one of its resources).
const std::vector<VarList> *ownerLists(const Instances &instances, const GlobalListRef &list)
{
    const Configuration *configuration = findConfiguration(instances, list.configuration);
    if (!configuration)
        return nullptr;
    if (list.resource.isEmpty())
        return &configuration->globalVars;
    for (const model::Resource &resource : configuration->resources) {
        if (sameName(resource.name, list.resource))
            return &resource.globalVars;
    }
    return nullptr;
}

std::vector<VarList> *ownerLists(Instances &instances, const GlobalListRef &list)
{
    return const_cast<std::vector<VarList> *>(ownerLists(std::as_const(instances), list));
}

bool belongsTo(const VarList &varList, const GlobalListRef &list)
{
    return sameName(varList.name.value_or(QString()), list.name);
}

GlobalListRef renamed(GlobalListRef list, const QString &name)
{
    list.name = name;
    return list;
}

} // namespace

QString GlobalListRef::displayName() const
{
    if (!name.isEmpty())
        return name;
    return resource.isEmpty() ? configuration : resource;
}

QString GlobalListRef::key() const
{
    return QStringLiteral("%1/%2/%3").arg(configuration.toLower(), resource.toLower(), name.toLower());
}

std::vector<GlobalListRef> globalLists(const Instances &instances)
{
    std::vector<GlobalListRef> result;
    const auto collect = [&](const std::vector<VarList> &lists, const QString &configuration, const QString &resource) {
        for (const VarList &list : lists) {
            const GlobalListRef ref {configuration, resource, list.name.value_or(QString())};
            if (std::ranges::none_of(result, [&](const GlobalListRef &known) { return known.sameList(ref); }))
                result.push_back(ref);
        }
    };
    for (const Configuration &configuration : instances.configurations) {
        collect(configuration.globalVars, configuration.name, {});
        for (const model::Resource &resource : configuration.resources)
            collect(resource.globalVars, configuration.name, resource.name);
    }
    return result;
}

bool globalListExists(const Instances &instances, const GlobalListRef &list)
{
    const std::vector<VarList> *lists = ownerLists(instances, list);
    return lists && std::ranges::any_of(*lists, [&](const VarList &varList) { return belongsTo(varList, list); });
}

model::Interface globalListDeclarations(const Instances &instances, const GlobalListRef &list)
{
    model::Interface declarations;
    if (const std::vector<VarList> *lists = ownerLists(instances, list)) {
        for (const VarList &varList : *lists) {
            if (belongsTo(varList, list))
                declarations.varLists.push_back(varList);
        }
    }
    return declarations;
}

std::optional<Instances> withGlobalListDeclarations(
    const Instances &instances, const GlobalListRef &list, const model::Interface &declarations)
{
    if (!globalListExists(instances, list))
        return std::nullopt;
    Instances result = instances;
    std::vector<VarList> &lists = *ownerLists(result, list);
    std::vector<VarList> replacement = declarations.varLists;
    for (VarList &varList : replacement) {
        varList.kind = model::VarListKind::Global;
        varList.name = list.name.isEmpty() ? std::nullopt : std::optional(list.name);
    }
    // A list whose last variable was removed stays in the project as an empty list: it is
    // removed from the tree, not by emptying it.
    if (replacement.empty()) {
        replacement.push_back({});
        replacement.back().kind = model::VarListKind::Global;
        replacement.back().name = list.name.isEmpty() ? std::nullopt : std::optional(list.name);
    }
    std::vector<size_t> places;
    for (size_t index = 0; index < lists.size(); ++index) {
        if (belongsTo(lists[index], list))
            places.push_back(index);
    }
    // As many sections as before: each stays where it was, so the file changes where the list did.
    if (places.size() == replacement.size()) {
        for (size_t i = 0; i < places.size(); ++i)
            lists[places[i]] = std::move(replacement[i]);
        return result;
    }
    // Otherwise the sections stand together where the first one was.
    std::erase_if(lists, [&](const VarList &varList) { return belongsTo(varList, list); });
    lists.insert(lists.begin() + std::ptrdiff_t(places.front()), replacement.begin(), replacement.end());
    return result;
}

std::optional<GlobalListRef> defaultGlobalListOwner(const Instances &instances)
{
    if (instances.configurations.empty())
        return std::nullopt;
    const Configuration &configuration = instances.configurations.front();
    if (configuration.resources.empty())
        return GlobalListRef {configuration.name, {}, {}};
    return GlobalListRef {configuration.name, configuration.resources.front().name, {}};
}

QString implicitProgram(const model::Project &project)
{
    std::vector<const model::Pou *> programs;
    for (const model::Pou &pou : project.types.pous) {
        if (pou.kind == model::PouKind::Program)
            programs.push_back(&pou);
    }
    if (programs.empty())
        return {};
    if (programs.size() > 1) {
        for (const QString &preferred : {QStringLiteral("PLC_PRG"), QStringLiteral("Main")}) {
            const auto it = std::ranges::find_if(programs, [&](const model::Pou *p) { return sameName(p->name, preferred); });
            if (it != programs.end())
                return (*it)->name;
        }
    }
    return programs.front()->name;
}

Instances withExplicitConfiguration(const Instances &instances, const QString &program, const QString &interval)
{
    if (!instances.configurations.empty())
        return instances;
    model::Task task;
    task.name = QStringLiteral("MainTask");
    task.interval = interval;
    task.priority = 1;
    if (!program.isEmpty())
        task.pouInstances.push_back({.name = program, .typeName = program});
    model::Resource resource;
    resource.name = QStringLiteral("Resource");
    resource.tasks.push_back(std::move(task));
    Configuration configuration;
    configuration.name = QStringLiteral("Config");
    configuration.resources.push_back(std::move(resource));
    Instances result = instances;
    result.configurations.push_back(std::move(configuration));
    return result;
}

std::optional<GlobalListEdit> withGlobalListAdded(const Instances &instances, const GlobalListRef &owner, const QString &name)
{
    Instances result = instances;
    std::vector<VarList> *lists = ownerLists(result, owner);
    if (!lists)
        return std::nullopt;
    VarList list;
    list.kind = model::VarListKind::Global;
    list.name = name;
    lists->push_back(std::move(list));
    return GlobalListEdit {std::move(result), renamed(owner, name)};
}

std::optional<GlobalListEdit> withGlobalListRenamed(const Instances &instances, const GlobalListRef &list, const QString &newName)
{
    if (!globalListExists(instances, list))
        return std::nullopt;
    Instances result = instances;
    for (VarList &varList : *ownerLists(result, list)) {
        if (belongsTo(varList, list))
            varList.name = newName.isEmpty() ? std::nullopt : std::optional(newName);
    }
    return GlobalListEdit {std::move(result), renamed(list, newName)};
}

std::optional<GlobalListEdit> withGlobalListDuplicated(
    const Instances &instances, const GlobalListRef &list, const QString &copyName)
{
    if (!globalListExists(instances, list))
        return std::nullopt;
    Instances result = instances;
    std::vector<VarList> &lists = *ownerLists(result, list);
    std::vector<VarList> copies;
    for (const VarList &varList : lists) {
        if (!belongsTo(varList, list))
            continue;
        VarList copy = varList;
        copy.name = copyName;
        for (model::Variable &variable : copy.variables)
            variable.globalId.reset(); // ids name one object in the file
        copies.push_back(std::move(copy));
    }
    const auto last = std::ranges::find_if(lists.rbegin(), lists.rend(), [&](const VarList &v) { return belongsTo(v, list); });
    lists.insert(last.base(), copies.begin(), copies.end());
    return GlobalListEdit {std::move(result), renamed(list, copyName)};
}

std::optional<Instances> withGlobalListRemoved(const Instances &instances, const GlobalListRef &list)
{
    if (!globalListExists(instances, list))
        return std::nullopt;
    Instances result = instances;
    std::erase_if(*ownerLists(result, list), [&](const VarList &varList) { return belongsTo(varList, list); });
    return result;
}

namespace {

std::optional<GlobalListRef> firstListDeclaring(const Instances &instances, const QString &variable,
    const std::function<bool(const GlobalListRef &)> &candidate)
{
    for (const GlobalListRef &list : globalLists(instances)) {
        if (!candidate(list))
            continue;
        for (const VarList &varList : globalListDeclarations(instances, list).varLists) {
            if (std::ranges::any_of(varList.variables, [&](const model::Variable &v) { return sameName(v.name, variable); }))
                return list;
        }
    }
    return std::nullopt;
}

} // namespace

std::optional<GlobalListRef> otherListDeclaring(
    const Instances &instances, const QString &configuration, const QString &variable, const GlobalListRef &except)
{
    return firstListDeclaring(instances, variable, [&](const GlobalListRef &list) {
        return sameName(list.configuration, configuration) && !list.sameList(except);
    });
}

std::optional<GlobalListRef> globalListDeclaring(const Instances &instances, const QString &variable, const QString &listName)
{
    return firstListDeclaring(instances, variable,
        [&](const GlobalListRef &list) { return listName.isEmpty() || sameName(list.displayName(), listName); });
}

} // namespace iec::editors
