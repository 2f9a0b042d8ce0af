#pragma once

#include <QString>
#include <QtGlobal>

#include <vector>

namespace iec::interp {

// Where something is in the user's program: the POU (empty for declarations outside any POU)
// and a 1-based line and column in the text it came from; an element of a graphical body (LD, FBD,
// SFC) has its localId instead. localId is 64-bit: CODESYS writes ids around 1e10.
struct SourceLocation {
    int line = 0;
    int column = 0;
    qint64 localId = -1; // -1: none
    // What the debugger's line table names for graphical code when it is not localId (only the
    // line table reads it, never a diagnostic): an LD/FBD network (the localId of its first
    // root), an SFC transition's firing; kNoPlace for code that is no place of its own.
    qint64 place = -1;
    static constexpr qint64 kNoPlace = -2;
};

struct Diagnostic {
    enum class Severity { Error, Warning };
    Severity severity = Severity::Error;
    QString pou;
    SourceLocation location;
    QString message; // one sentence a student understands
    QString hint;    // what to do, when it is obvious; may be empty
    // An {error '...'} pragma: the author's own message. The text around it read fine, so it is
    // still type checked and opened in the IDE; the program does not run.
    bool requested = false;

    // "Main:3:7: error: ... (hint: ...)"
    QString toString() const;
};

class Diagnostics
{
public:
    void error(const QString &pou, SourceLocation at, const QString &message, const QString &hint = {});
    void warning(const QString &pou, SourceLocation at, const QString &message, const QString &hint = {});
    void requestedError(const QString &pou, SourceLocation at, const QString &message);
    bool hasErrors() const { return m_errors > 0; }
    // Errors other than requested ones: the text did not read, or the program is wrong.
    bool hasUnrequestedErrors() const { return m_errors > m_requestedErrors; }
    const std::vector<Diagnostic> &all() const { return m_list; }
    void append(const Diagnostics &other);

private:
    std::vector<Diagnostic> m_list;
    int m_errors = 0;
    int m_requestedErrors = 0;
};

} // namespace iec::interp
