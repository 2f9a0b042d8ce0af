#pragma once

#include "interpreter/runtime/snapshot.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <vector>

namespace iec::editors {

// An editor that can show the running program (DESIGN.md: an overlay restyles items from the
// latest snapshot and never touches the model). The app's online controller asks each open
// editor which names it wants, puts them in the snapshots it publishes, and hands every new
// snapshot to every open editor.
class OnlineView
{
public:
    virtual ~OnlineView() = default;

    // The instance whose values this editor shows ("Main" for a program; an FB's editor picks
    // one of its instances). Empty: the editor shows nothing online.
    virtual QString onlineInstance() const = 0;
    // Names (full paths such as "Main.Count") whose values the editor shows.
    virtual QStringList onlineNames() const = 0;
    // Whether the editor shows the chart state (active steps, step times) of onlineInstance():
    // the controller then asks the runtime for that instance's chart (SFC editors say yes).
    virtual bool wantsChartState() const { return false; }
    // nullptr leaves online mode: the editor drops every overlay and becomes editable again.
    // While online the editor refuses edits with a clear message.
    virtual void setOnlineSnapshot(const interp::RuntimeSnapshot *snapshot) = 0;

    // Debugging. A place in this body a breakpoint can be on: a line of a text body, or the
    // element (localId) of a graphical one.
    struct Place {
        int line = 0;
        qint64 localId = -1;          // graphical: the element that names the place
        std::vector<qint64> elements; // graphical: every element it stands for (an LD/FBD network's)
        bool enabled = true;          // a breakpoint switched off is drawn hollow
        // Two places are one when they name the same line or element, whatever else they hold.
        bool operator==(const Place &other) const { return line == other.line && localId == other.localId; }
    };
    // Where the cursor is, for Toggle Breakpoint (F9); nullopt where no breakpoint can be.
    virtual std::optional<Place> breakpointPlace() const { return std::nullopt; }
    // The breakpoints of this body, shown offline and online, and the place the program is
    // halted at when it is in this body.
    virtual void setBreakpointMarks(const std::vector<Place> &breakpoints, std::optional<Place> halted)
    {
        (void)breakpoints;
        (void)halted;
    }
    // How the status bar names a place of this body ("network 3"); empty: the app says "element N".
    virtual QString placeName(qint64 localId) const
    {
        (void)localId;
        return {};
    }
    // Called when the user toggles a breakpoint in the editor itself (a click in the margin).
    void setBreakpointToggle(std::function<void(const Place &)> toggle) { m_breakpointToggle = std::move(toggle); }

protected:
    void requestBreakpointToggle(const Place &place) const
    {
        if (m_breakpointToggle)
            m_breakpointToggle(place);
    }

private:
    std::function<void(const Place &)> m_breakpointToggle;
};

} // namespace iec::editors
