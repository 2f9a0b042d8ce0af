#pragma once

#include "editors/common/overlaymapper.h"

#include <QHash>

namespace iec::editors::cfc {

class CfcPolicy;

// The online overlay of a CFC, as FBD's: each variable's value after its name, the outputs of
// boxes beside their pins, TRUE wires thick and blue, forced values marked. The values of function
// outputs come from the same computation FBD uses (fbdvalues.h); inside a feedback loop they stay
// unknown and only the variables show theirs.
class CfcOverlayMapper : public OverlayMapper
{
public:
    explicit CfcOverlayMapper(const CfcPolicy &policy);

    QStringList names(const DiagramScene &scene, const QString &instance) const override;
    void apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance) override;
    void clear(DiagramScene &scene) override;

    // The name the runtime knows a variable element by ("Main.Count"); empty for constants and
    // other elements.
    [[nodiscard]] QString variableName(const DiagramScene &scene, quint64 localId, const QString &instance) const;
    [[nodiscard]] QString value(const QString &name) const { return m_values.value(name); }

private:
    const CfcPolicy &m_policy;
    QHash<QString, QString> m_values;
};

} // namespace iec::editors::cfc
