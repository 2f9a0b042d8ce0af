#pragma once

#include <QString>
#include <QtGlobal>

#include <vector>

namespace iec::editors {

// What a pure edit of a body's elements says: done (and what to select afterwards), or why it
// refuses, in a sentence the user reads. Every language's edit functions return it.
struct EditOutcome {
    QString error; // empty: done
    std::vector<quint64> select;

    [[nodiscard]] bool ok() const { return error.isEmpty(); }
};

} // namespace iec::editors
