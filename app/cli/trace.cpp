#include "app/cli/trace.h"

#include "app/cli/trace_csv.h"
#include "app/cli/trace_vcd.h"

namespace iec::cli {

Trace::Trace(const QString &path, std::vector<TracedVariable> variables)
    : m_file(path)
    , m_variables(std::move(variables))
{ }

bool Trace::finish(QString &error)
{
    m_stream.flush();
    if (m_file.error() != QFile::NoError || !m_file.flush()) {
        error = QStringLiteral("%1 could not be written: %2.").arg(m_file.fileName(), m_file.errorString());
        return false;
    }
    m_file.close();
    return true;
}

OpenedTrace openTrace(const QString &path, std::vector<TracedVariable> variables)
{
    OpenedTrace opened;
    if (path.endsWith(QLatin1String(".vcd"), Qt::CaseInsensitive)) {
        if (!interp::vcdCanHold(variables, opened.error))
            return opened;
        opened.trace = std::make_unique<VcdTrace>(path, std::move(variables));
    } else {
        opened.trace = std::make_unique<CsvTrace>(path, std::move(variables));
    }
    Trace &trace = *opened.trace;
    if (!trace.m_file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        opened.error = QStringLiteral("%1 cannot be created: %2.").arg(path, trace.m_file.errorString());
        opened.fileError = true;
        opened.trace.reset();
        return opened;
    }
    trace.m_stream.setDevice(&trace.m_file);
    return opened;
}

} // namespace iec::cli
