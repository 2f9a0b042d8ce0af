#include "app/importexport.h"

#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/projectmodel.h"
#include "model/undo/datatypecommands.h"
#include "model/undo/poucommands.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QSet>
#include <QUndoCommand>

#include <algorithm>

namespace iec::app {

namespace {

Message::Severity severityOf(model::Diagnostic::Severity severity)
{
    switch (severity) {
    case model::Diagnostic::Severity::Info:
        return Message::Severity::Info;
    case model::Diagnostic::Severity::Warning:
        return Message::Severity::Warning;
    case model::Diagnostic::Severity::Error:
        break;
    }
    return Message::Severity::Error;
}

// The first name "<name>_N" (N = 1, 2, ...) that `taken` does not hold (upper case).
QString freeName(const QString &name, const QSet<QString> &taken)
{
    if (!taken.contains(name.toUpper()))
        return name;
    for (int n = 1;; ++n) {
        const QString candidate = QStringLiteral("%1_%2").arg(name).arg(n);
        if (!taken.contains(candidate.toUpper()))
            return candidate;
    }
}

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

} // namespace

ImportExport::Format ImportExport::formatOf(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("st") || suffix == QLatin1String("iec") || suffix == QLatin1String("txt")
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
            result.messages.append({.severity = severityOf(diagnostic.severity),
                .text = diagnostic.message,
                .pouName = diagnostic.pouName.value_or(fileName),
                .line = diagnostic.line,
                .column = diagnostic.column});
        }
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
    const QString text = QString::fromUtf8(file.readAll());
    interp::frontend::TextReadResult iec = interp::frontend::readIecText(text, QFileInfo(path).completeBaseName());
    for (const interp::Diagnostic &diagnostic : iec.diagnostics.all()) {
        result.messages.append({.severity = diagnostic.severity == interp::Diagnostic::Severity::Error
                                    ? Message::Severity::Error
                                    : Message::Severity::Warning,
            .text = diagnostic.message,
            .pouName = diagnostic.pou.isEmpty() ? fileName : diagnostic.pou,
            .line = diagnostic.location.line,
            .column = diagnostic.location.column});
    }
    result.project = std::move(iec.project);
    return result;
}

ImportExport::Merge ImportExport::merge(model::ProjectModel &model, const model::Project &imported)
{
    Merge result;
    QSet<QString> taken = namesInUse(model.project());
    auto *command = new QUndoCommand;
    const auto note = [&](const QString &oldName, const QString &newName) {
        result.messages.append({.severity = Message::Severity::Warning,
            .text = tr("%1 exists already; the imported one is named %2.").arg(oldName, newName),
            .pouName = newName});
    };
    for (model::DataTypeDecl type : imported.types.dataTypes) {
        const QString name = freeName(type.name, taken);
        if (name != type.name)
            note(type.name, name);
        type.name = name;
        type.addDataSlot = 0; // an ordinary type of this project now
        taken.insert(name.toUpper());
        new model::AddDataTypeCommand(model, std::move(type), command);
        ++result.dataTypes;
    }
    for (model::Pou pou : imported.types.pous) {
        const QString name = freeName(pou.name, taken);
        if (name != pou.name)
            note(pou.name, name);
        pou.name = name;
        pou.id = {}; // the project gives it an id of its own
        pou.addDataSlot = 0;
        taken.insert(name.toUpper());
        new model::AddPouCommand(model, std::move(pou), command);
        ++result.pous;
    }
    if (!imported.instances.configurations.empty()) {
        result.messages.append({.severity = Message::Severity::Info,
            .text = tr("The imported configurations were left out; the project keeps its own.")});
    }
    if (command->childCount() == 0) {
        delete command;
        return result;
    }
    command->setText(tr("Import %n object(s)", nullptr, result.pous + result.dataTypes));
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
    const model::Project part = selection(project, pous);
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
    // QSaveFile writes beside the target and renames: a failed export leaves the old file whole.
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        if (error)
            *error = tr("%1 cannot be written: %2").arg(QFileInfo(path).fileName(), file.errorString());
        return false;
    }
    return true;
}

} // namespace iec::app
