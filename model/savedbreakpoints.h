#pragma once

#include "model/project.h"

#include <QString>

#include <vector>

// The debugger's breakpoints as the project file keeps them: in our own addData of the project
// (other tools ignore it), by POU name so they survive a save and a load. The model only stores
// them; what they mean is the runtime's (interpreter/runtime/debugging.h).
namespace iec::model {

inline constexpr const char *kBreakpointsAddDataName = "https://iec-studio.org/breakpoints";

struct SavedBreakpoint {
    QString pou;
    QString action;              // empty: the POU's own body
    int line = 0;                // text bodies
    qint64 localId = -1;         // graphical bodies: the element that names the place
    std::vector<qint64> elements; // graphical bodies: every element of the place (a network's)
    int hitRule = 0;             // 0 always, 1 equal, 2 multiple of, 3 at least
    int hitTarget = 1;
    QString condition;
    bool enabled = true;

    bool operator==(const SavedBreakpoint &) const = default;
};

// The breakpoints saved in `project` (none when there is no entry or it does not read).
std::vector<SavedBreakpoint> savedBreakpoints(const Project &project);
// Replaces the entry; no breakpoints remove it, so a project without any is written as before.
void setSavedBreakpoints(Project &project, const std::vector<SavedBreakpoint> &breakpoints);

} // namespace iec::model
