#include "app/importexport.h"

#include "app/namerules.h"
#include "app/referencerename.h"

#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/sourcefile.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"
#include "model/savefile.h"
#include "model/undo/datatypecommands.h"
#include "model/undo/instancecommands.h"
#include "model/undo/poucommands.h"

#include <QFile>
#include <QFileInfo>
#include <QSet>
#include <QUndoCommand>

#include <algorithm>
#include <functional>
#include <iterator>
#include <memory>

namespace iec::app {

namespace {

QSet<QString> namesInUse(const model::Project &project)
{
    // POUs and data types share one namespace in IEC 61131-3.
    QSet<QString> taken;
    for (const model::Pou &pou : project.types.pous)
        taken.insert(pou.name.toUpper());
    for (const model::DataTypeDecl &type : project.types.dataTypes)
        taken.insert(type.name.toUpper());
    return taken;
}

// Gives names to imported things so that none clashes with the project: a name the project has
// becomes the first free "<name>_N" (NameRules::firstFree), never one the project or the
// import already uses, so two generated names cannot meet either.
class FreeNames
{
public:
    FreeNames(QSet<QString> projectNames, const QStringList &importedNames)
        : m_projectNames(std::move(projectNames))
        , m_taken(m_projectNames)
    {
        for (const QString &name : importedNames)
            m_taken.insert(name.toUpper());
    }

    QString operator()(const QString &name)
    {
        const QString upper = name.toUpper();
        QString free = name;
        if (m_projectNames.contains(upper) || m_given.contains(upper))
            free = NameRules::firstFree(name, [this](const QString &n) { return m_taken.contains(n.toUpper()); });
        m_taken.insert(free.toUpper());
        m_given.insert(free.toUpper());
        return free;
    }

private:
    QSet<QString> m_projectNames;
    QSet<QString> m_taken;
    QSet<QString> m_given;
};

} // namespace

ImportExport::Format ImportExport::formatOf(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("st") || suffix == QLatin1String("exp") || suffix == QLatin1String("iec")
            || suffix == QLatin1String("txt")
        ? Format::IecText
        : Format::PlcOpenXml;
}

ImportExport::Read ImportExport::read(const QString &path)
{
    Read result;
    const QString fileName = QFileInfo(path).fileName();
    if (formatOf(path) == Format::PlcOpenXml) {
        model::plcopen::ReadResult xml = model::plcopen::readProjectFile(path);
        for (const model::Diagnostic &diagnostic : xml.diagnostics) {
            result.messages.append({.severity = messageSeverity(diagnostic.severity),
                .text = diagnostic.message,
                .pouName = diagnostic.pouName.value_or(fileName),
                .line = diagnostic.line,
                .column = diagnostic.column});
        }
        result.whole = xml.ok;
        if (!xml.fileError && xml.isProject)
            result.project = std::move(xml.project);
        else if (result.messages.isEmpty())
            result.messages.append({.text = tr("%1 is not a PLCopen XML project.").arg(fileName)});
        return result;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        result.messages.append({.text = tr("%1 cannot be read: %2").arg(fileName, file.errorString())});
        return result;
    }
    const interp::frontend::SourceText source = interp::frontend::decodeSourceFile(file.readAll());
    if (source.windows1252Line > 0)
        result.messages.append({.severity = Message::Severity::Warning,
            .text = interp::frontend::windows1252Note(),
            .pouName = fileName,
            .line = source.windows1252Line,
            .column = 1});
    interp::frontend::TextReadResult iec = interp::frontend::readIecText(source.text, QFileInfo(path).completeBaseName());
    for (const interp::Diagnostic &diagnostic : iec.diagnostics.all()) {
        result.messages.append({.severity = diagnostic.severity == interp::Diagnostic::Severity::Error
                                    ? Message::Severity::Error
                                    : Message::Severity::Warning,
            .text = diagnostic.message,
            .pouName = diagnostic.pou.isEmpty() ? fileName : diagnostic.pou,
            .line = diagnostic.location.line,
            .column = diagnostic.location.column});
    }
    result.whole = !iec.diagnostics.hasUnrequestedErrors();
    result.project = std::move(iec.project);
    return result;
}

namespace {

using Note = std::function<void(const QString &oldName, const QString &newName)>;

QStringList globalNames(const model::Instances &instances)
{
    QStringList names;
    const auto add = [&](const std::vector<model::VarList> &lists) {
        for (const model::VarList &list : lists) {
            for (const model::Variable &variable : list.variables)
                names.append(variable.name);
        }
    };
    for (const model::Configuration &configuration : instances.configurations) {
        add(configuration.globalVars);
        for (const model::Resource &resource : configuration.resources)
            add(resource.globalVars);
    }
    return names;
}

QSet<QString> upperSet(const QStringList &names)
{
    QSet<QString> set;
    for (const QString &name : names)
        set.insert(name.toUpper());
    return set;
}

// The imported project with its globals renamed where the project has a global of that name;
// the imported POUs that use them follow (the same rename as an interactive one).
model::Project withFreeGlobals(const model::Project &imported, const model::Instances &project, const Note &note)
{
    FreeNames freeNames(upperSet(globalNames(project)), globalNames(imported.instances));
    model::ProjectModel staging;
    staging.reset(imported);
    for (const QString &name : globalNames(imported.instances)) {
        const QString free = freeNames(name);
        if (free == name)
            continue;
        note(name, free);
        std::unique_ptr<QUndoCommand> rename(createRenameGlobalVariableCommand(staging, name, free));
        rename->redo();
    }
    return staging.project();
}

QStringList instanceNames(const model::Resource &resource)
{
    QStringList names;
    for (const model::PouInstance &instance : resource.pouInstances)
        names.append(instance.name);
    for (const model::Task &task : resource.tasks) {
        for (const model::PouInstance &instance : task.pouInstances)
            names.append(instance.name);
    }
    return names;
}

// Adds the imported resource's globals, tasks and program instances to `into`; tasks and
// instances whose names `into` has get free ones.
void mergeResource(model::Resource &into, model::Resource imported, const Note &note)
{
    std::ranges::move(imported.globalVars, std::back_inserter(into.globalVars));
    QStringList taskNames;
    for (const model::Task &task : imported.tasks)
        taskNames.append(task.name);
    QStringList intoTaskNames;
    for (const model::Task &task : into.tasks)
        intoTaskNames.append(task.name);
    FreeNames freeTasks(upperSet(intoTaskNames), taskNames);
    FreeNames freeInstances(upperSet(instanceNames(into)), instanceNames(imported));
    const auto rename = [&note](QString &name, FreeNames &freeNames) {
        const QString free = freeNames(name);
        if (free != name)
            note(name, free);
        name = free;
    };
    for (model::PouInstance &instance : imported.pouInstances) {
        rename(instance.name, freeInstances);
        into.pouInstances.push_back(std::move(instance));
    }
    for (model::Task &task : imported.tasks) {
        rename(task.name, freeTasks);
        for (model::PouInstance &instance : task.pouInstances)
            rename(instance.name, freeInstances);
        into.tasks.push_back(std::move(task));
    }
}

// VAR_ACCESS and VAR_CONFIG lists of a configuration: the imported variables join the project's.
template<class List> void appendVariables(std::optional<List> &into, const std::optional<List> &imported)
{
    if (!imported)
        return;
    if (!into) {
        into = imported;
        return;
    }
    std::ranges::copy(imported->variables, std::back_inserter(into->variables));
}

template<class T> T *findNamed(std::vector<T> &values, const QString &name)
{
    const auto it = std::ranges::find_if(
        values, [&](const T &value) { return value.name.compare(name, Qt::CaseInsensitive) == 0; });
    return it == values.end() ? nullptr : &*it;
}

} // namespace

void ImportExport::mergeConfigurations(model::Instances &into, const model::Instances &imported, QList<Message> &messages)
{
    for (const model::Configuration &configuration : imported.configurations) {
        if (into.configurations.empty()) {
            into.configurations.push_back(configuration);
            continue;
        }
        model::Configuration *target = findNamed(into.configurations, configuration.name);
        if (!target) {
            // Only a project's first configuration runs: a second one would be silently idle.
            target = &into.configurations.front();
            messages.append({.severity = Message::Severity::Info,
                .text = tr("The imported configuration %1 joins the project's configuration %2.")
                            .arg(configuration.name, target->name)});
        }
        std::ranges::copy(configuration.globalVars, std::back_inserter(target->globalVars));
        appendVariables(target->accessVars, configuration.accessVars);
        appendVariables(target->configVars, configuration.configVars);
        for (const model::Resource &resource : configuration.resources) {
            if (model::Resource *same = findNamed(target->resources, resource.name))
                mergeResource(*same, resource, [&](const QString &oldName, const QString &newName) {
                    messages.append({.severity = Message::Severity::Warning,
                        .text = tr("%1 exists already in resource %2; the imported one is named %3.")
                                    .arg(oldName, resource.name, newName)});
                });
            else
                target->resources.push_back(resource);
        }
    }
}

ImportExport::Merge ImportExport::merge(model::ProjectModel &model, const model::Project &imported)
{
    Merge result;
    const model::Project &project = model.project();
    const Note note = [&](const QString &oldName, const QString &newName) {
        result.messages.append({.severity = Message::Severity::Warning,
            .text = tr("%1 exists already; the imported one is named %2.").arg(oldName, newName),
            .pouName = newName});
    };
    // POUs and data types first: the imported bodies, declarations and tasks follow their renames.
    QStringList importedNames;
    for (const model::DataTypeDecl &type : imported.types.dataTypes)
        importedNames.append(type.name);
    for (const model::Pou &pou : imported.types.pous)
        importedNames.append(pou.name);
    FreeNames freeNames(namesInUse(project), importedNames);
    Renames renames;
    for (const QString &name : importedNames) {
        const QString free = freeNames(name);
        if (free != name) {
            note(name, free);
            renames.push_back({name, free});
        }
    }
    model::Project incoming = projectWithTypesRenamed(imported, renames);
    incoming = withFreeGlobals(incoming, project.instances, note);

    auto *command = new QUndoCommand;
    for (model::DataTypeDecl type : incoming.types.dataTypes) {
        type.addDataSlot = 0; // an ordinary type of this project now
        new model::AddDataTypeCommand(model, std::move(type), command);
        ++result.dataTypes;
    }
    for (model::Pou pou : incoming.types.pous) {
        pou.id = {}; // the project gives it an id of its own
        pou.addDataSlot = 0;
        new model::AddPouCommand(model, std::move(pou), command);
        ++result.pous;
    }
    model::Instances instances = project.instances;
    mergeConfigurations(instances, incoming.instances, result.messages);
    if (instances != project.instances) {
        new model::SetInstancesCommand(model, std::move(instances), command);
        result.configurations = int(incoming.instances.configurations.size());
    }
    if (command->childCount() == 0) {
        delete command;
        return result;
    }
    command->setText(tr("Import %n object(s)", nullptr, result.pous + result.dataTypes + result.configurations));
    result.command = command;
    return result;
}

model::Project ImportExport::selection(const model::Project &project, const std::vector<model::PouId> &pous)
{
    if (pous.empty())
        return project;
    model::Project part;
    part.fileHeader = project.fileHeader;
    part.contentHeader = project.contentHeader;
    part.types.dataTypes = project.types.dataTypes;
    for (const model::Pou &pou : project.types.pous) {
        if (std::ranges::find(pous, pou.id) != pous.end())
            part.types.pous.push_back(pou);
    }
    return part;
}

bool ImportExport::write(const model::Project &project, const std::vector<model::PouId> &pous, Format format,
    const QString &path, QString *error, QList<Message> *warnings)
{
    model::Project part = selection(project, pous);
    model::plcopen::stampCreationTime(part.fileHeader, QDateTime::currentDateTimeUtc());
    QByteArray bytes;
    if (format == Format::PlcOpenXml) {
        bytes = model::plcopen::writeProject(part);
    } else {
        std::vector<interp::frontend::PrintWarning> printWarnings;
        bytes = interp::frontend::printProject(part, &printWarnings).toUtf8();
        for (const interp::frontend::PrintWarning &warning : printWarnings) {
            if (warnings)
                warnings->append({.severity = Message::Severity::Warning, .text = warning.message, .pouName = warning.pou});
        }
    }
    // A failed export leaves the old file whole.
    return model::saveFileAtomically(path, bytes, error);
}

} // namespace iec::app
