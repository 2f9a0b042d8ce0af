#include "app/online/breakpointlines.h"

#include <algorithm>

namespace iec::app {

int lineAfterEdit(int line, const QStringList &before, const QStringList &after)
{
    const qsizetype shorter = std::min(before.size(), after.size());
    qsizetype same = 0; // equal lines at the start
    while (same < shorter && before[same] == after[same])
        ++same;
    qsizetype sameEnd = 0; // equal lines at the end, not overlapping those at the start
    while (sameEnd < shorter - same && before[before.size() - 1 - sameEnd] == after[after.size() - 1 - sameEnd])
        ++sameEnd;
    if (line <= same)
        return line;
    if (line > before.size() - sameEnd)
        return int(line + after.size() - before.size());
    const qsizetype editedEnd = after.size() - sameEnd; // the edited part of `after` is same+1 .. editedEnd
    if (editedEnd <= same)
        return 0;
    return int(std::min<qsizetype>(line, editedEnd));
}

} // namespace iec::app
