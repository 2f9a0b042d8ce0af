#pragma once

#include <QString>

#include <optional>

namespace iec::model {

// One finding of the reader (or a later stage): what, where in the file and, when known, in
// which POU and graphical element.
struct Diagnostic {
    enum class Severity { Info, Warning, Error };

    Severity severity = Severity::Error;
    QString message; // one clear sentence
    int line = 0; // 1-based; 0 when unknown
    int column = 0; // 1-based; 0 when unknown
    std::optional<QString> pouName;
    std::optional<quint64> localId;

    bool operator==(const Diagnostic &) const = default;
};

} // namespace iec::model
