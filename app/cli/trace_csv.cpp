#include "app/cli/trace_csv.h"

namespace iec::cli {

namespace {

// RFC 4180: a field with a comma, a quote or a line break is quoted, its quotes doubled.
QString csvField(const QString &text)
{
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) && !text.contains(QLatin1Char('\n')))
        return text;
    QString quoted = text;
    quoted.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

} // namespace

void CsvTrace::begin(interp::Runtime &)
{
    out() << "cycle,time_ms";
    for (const TracedVariable &variable : variables())
        out() << ',' << csvField(variable.name);
    out() << '\n';
}

void CsvTrace::sample(int cycle, interp::Runtime &runtime)
{
    out() << cycle << ',' << formatMilliseconds(runtime.timeNs());
    for (const TracedVariable &variable : variables())
        out() << ',' << csvField(runtime.read(variable.ref));
    out() << '\n';
}

} // namespace iec::cli
