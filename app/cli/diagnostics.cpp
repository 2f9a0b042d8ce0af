#include "app/cli/diagnostics.h"

namespace iec::cli {

namespace {

const char *severityName(model::Diagnostic::Severity severity)
{
    switch (severity) {
    case model::Diagnostic::Severity::Error:
        return "error";
    case model::Diagnostic::Severity::Warning:
        return "warning";
    case model::Diagnostic::Severity::Info:
        return "note";
    }
    return "";
}

} // namespace

void printDiagnostics(const QString &file, const std::vector<model::Diagnostic> &diagnostics, QTextStream &stream)
{
    for (const model::Diagnostic &diagnostic : diagnostics) {
        stream << file << ":";
        if (diagnostic.line > 0)
            stream << diagnostic.line << ":" << diagnostic.column << ":";
        stream << " " << severityName(diagnostic.severity) << ": " << diagnostic.message;
        if (diagnostic.pouName)
            stream << " [pou " << *diagnostic.pouName << "]";
        if (diagnostic.localId)
            stream << " [localId " << *diagnostic.localId << "]";
        stream << "\n";
    }
}

} // namespace iec::cli
