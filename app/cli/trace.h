#pragma once

#include "interpreter/runtime/runtime.h"
#include "interpreter/runtime/tracedata.h"

#include <QFile>
#include <QString>
#include <QTextStream>

#include <memory>
#include <vector>

namespace iec::cli {

using TracedVariable = interp::TraceVariable;

// Records the watched variables after every cycle (formats: docs/cli.md).
class Trace
{
public:
    virtual ~Trace() = default;
    // Called once before the first cycle, with the initial values in `runtime`.
    virtual void begin(interp::Runtime &runtime) = 0;
    // Called after cycle `cycle` ran; runtime.timeNs() is the virtual time at its end.
    virtual void sample(int cycle, interp::Runtime &runtime) = 0;
    // Flushes the file; false and `error` when it could not be written.
    bool finish(QString &error);

protected:
    Trace(const QString &path, std::vector<TracedVariable> variables);
    QTextStream &out() { return m_stream; }
    const std::vector<TracedVariable> &variables() const { return m_variables; }

private:
    QFile m_file;
    QTextStream m_stream;
    std::vector<TracedVariable> m_variables;
    friend struct OpenedTrace openTrace(const QString &, std::vector<TracedVariable>);
};

struct OpenedTrace {
    std::unique_ptr<Trace> trace; // nullptr on failure
    QString error;
    bool fileError = false; // the file could not be created (else: a variable has no VCD form)
};

// A CSV trace for OUT.csv, a VCD trace for OUT.vcd. Fails when the file cannot be created or
// (VCD) a variable is not a BOOL, number, bit string, enum or time.
OpenedTrace openTrace(const QString &path, std::vector<TracedVariable> variables);

} // namespace iec::cli
