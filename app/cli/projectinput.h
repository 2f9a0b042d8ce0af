#pragma once

#include "app/cli/commands.h"

#include "interpreter/compiler/diagnostics.h"
#include "interpreter/frontend/projectsource.h"

#include "model/project.h"

#include <optional>

namespace iec::cli {

enum class FileFormat { Xml, St, Other };
FileFormat formatOf(const QString &path); // by extension, case-insensitive

// A project read from FILE (.xml or .st). `status` is ExitOk, ExitFailed (the file has errors,
// already printed) or ExitIoError (it cannot be read, already printed).
struct LoadedProject {
    int status = ExitOk;
    model::Project project;
};

// Reads FILE into the model: PLCopen XML with the model's reader, .st with the IEC text reader.
// Diagnostics go to `stream` in the formats of docs/cli.md.
LoadedProject loadProject(const QString &path, QTextStream &stream);

// Reads FILE as the compiler's input. A .st file is parsed as it is, so diagnostics carry lines
// of the file; an .xml file goes through the model (lines counted in each POU's body).
struct LoadedUnit {
    int status = ExitOk;
    interp::frontend::ProjectUnit unit;
};
LoadedUnit loadUnit(const QString &path, interp::Diagnostics &diagnostics, QTextStream &stream);

// The whole text of a file, or nullopt after printing why it cannot be read.
std::optional<QString> readTextFile(const QString &path, QTextStream &stream);

} // namespace iec::cli
