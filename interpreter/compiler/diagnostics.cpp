#include "interpreter/compiler/diagnostics.h"

namespace iec::interp {

QString Diagnostic::toString() const
{
    QString text = pou.isEmpty() ? QString() : pou + QLatin1Char(':');
    text += QString::number(location.line) + QLatin1Char(':') + QString::number(location.column) + QStringLiteral(": ");
    text += severity == Severity::Error ? QStringLiteral("error: ") : QStringLiteral("warning: ");
    text += message;
    if (!hint.isEmpty())
        text += QStringLiteral(" (hint: ") + hint + QLatin1Char(')');
    return text;
}

void Diagnostics::error(const QString &pou, SourceLocation at, const QString &message, const QString &hint)
{
    m_list.push_back({Diagnostic::Severity::Error, pou, at, message, hint});
    ++m_errors;
}

void Diagnostics::requestedError(const QString &pou, SourceLocation at, const QString &message)
{
    m_list.push_back({Diagnostic::Severity::Error, pou, at, message, {}, true});
    ++m_errors;
    ++m_requestedErrors;
}

void Diagnostics::warning(const QString &pou, SourceLocation at, const QString &message, const QString &hint)
{
    m_list.push_back({Diagnostic::Severity::Warning, pou, at, message, hint});
}

void Diagnostics::append(const Diagnostics &other)
{
    for (const Diagnostic &d : other.m_list) {
        m_list.push_back(d);
        if (d.severity == Diagnostic::Severity::Error) {
            ++m_errors;
            m_requestedErrors += d.requested ? 1 : 0;
        }
    }
}

} // namespace iec::interp
