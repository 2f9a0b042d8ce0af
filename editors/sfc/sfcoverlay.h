#pragma once

#include "editors/common/overlaymapper.h"

#include <vector>

namespace iec::editors::sfc {

class SfcPolicy;

// The SFC online overlay: active steps (and macro steps) filled blue with their elapsed time,
// transitions whose condition holds marked, the action rows of active steps coloured. Everything
// comes from the chart state of the instance (SFC steps are found by localId on the top level,
// by name inside macro steps).
class SfcOverlayMapper : public OverlayMapper
{
public:
    // `action`: the action whose body the chart is (empty: the POU's own chart).
    SfcOverlayMapper(const SfcPolicy &policy, QString action)
        : m_policy(policy)
        , m_action(std::move(action))
    { }

    [[nodiscard]] bool wantsChartState() const override { return true; }
    void apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance) override;
    void clear(DiagramScene &scene) override;

private:
    const SfcPolicy &m_policy;
    QString m_action;
};

// "T#1m3s200ms": a step's elapsed time as an IEC literal.
QString formatElapsed(std::int64_t ns);

} // namespace iec::editors::sfc
