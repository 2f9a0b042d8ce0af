#pragma once

#include <QString>
#include <QStringList>

namespace iec::interp {
struct RuntimeSnapshot;
}

namespace iec::editors {

class DiagramScene;

// What a language adds to the online overlay of a diagram editor (DESIGN.md: the overlay
// restyles items from the latest snapshot and never touches the model). The editor asks it which
// names to watch, hands it every snapshot (and again after the scene was rebuilt or updated, when
// items are new), and asks it to drop everything when going offline. A mapper restyles only the
// items whose state changed (DiagramItem's setters do nothing when the value is the same).
class OverlayMapper
{
public:
    virtual ~OverlayMapper() = default;

    // Full names ("Main.Start") whose values the overlay shows for `instance` ("Main", or
    // "Main.Filler" for a function block's editor).
    [[nodiscard]] virtual QStringList names(const DiagramScene &scene, const QString &instance) const
    {
        Q_UNUSED(scene);
        Q_UNUSED(instance);
        return {};
    }
    // Whether it needs the chart state of the instance (active steps: SFC).
    [[nodiscard]] virtual bool wantsChartState() const { return false; }
    // Shows the snapshot on the scene's items. It may show it on the part a view shows only: the
    // editor applies the last snapshot again when the view scrolls.
    virtual void apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance) = 0;
    virtual void clear(DiagramScene &scene) = 0;
};

} // namespace iec::editors
