#pragma once

#include "interpreter/runtime/snapshot.h"

#include <QString>
#include <QStringList>

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
};

} // namespace iec::editors
