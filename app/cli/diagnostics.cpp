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

QString formatDiagnostic(const QString &file, const interp::Diagnostic &diagnostic)
{
    QString text = file + QLatin1Char(':');
    if (!diagnostic.pou.isEmpty())
        text += diagnostic.pou + QLatin1Char(':');
    if (diagnostic.location.line > 0)
        text += QStringLiteral("%1:%2:").arg(diagnostic.location.line).arg(diagnostic.location.column);
    text += diagnostic.severity == interp::Diagnostic::Severity::Error ? QStringLiteral(" error: ")
                                                                       : QStringLiteral(" warning: ");
    text += diagnostic.message;
    if (!diagnostic.hint.isEmpty())
        text += QStringLiteral(" (hint: ") + diagnostic.hint + QLatin1Char(')');
    // An element of a graphical body has no line: name it the way the XML reader does.
    // (An inline transition condition's message also says where in the condition text.)
    if (diagnostic.location.line <= 0 && diagnostic.location.localId >= 0) {
        text += diagnostic.location.column > 0
            ? QStringLiteral(" [localId %1, column %2]").arg(diagnostic.location.localId).arg(diagnostic.location.column)
            : QStringLiteral(" [localId %1]").arg(diagnostic.location.localId);
    }
    return text;
}

void printDiagnostics(const QString &file, const interp::Diagnostics &diagnostics, QTextStream &stream)
{
    for (const interp::Diagnostic &diagnostic : diagnostics.all())
        stream << formatDiagnostic(file, diagnostic) << "\n";
}

} // namespace iec::cli
