#pragma once

#include "editors/common/overlaymapper.h"
#include "editors/ld/ldpowerflow.h"

namespace iec::editors::ld {

class LdPolicy;

// The online overlay of a ladder diagram: closed contacts and energised coils thick and blue,
// powered wires blue, the values of box pins and of variables beside them, forced values marked.
class LdOverlayMapper : public OverlayMapper
{
public:
    explicit LdOverlayMapper(const LdPolicy &policy);

    QStringList names(const DiagramScene &scene, const QString &instance) const override;
    void apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance) override;
    void clear(DiagramScene &scene) override;

    // The name the runtime knows an element's variable by (contacts, coils, variables), empty for
    // other elements.
    [[nodiscard]] QString variableName(quint64 localId, const QString &instance) const;
    // The value of a name in the last snapshot applied.
    [[nodiscard]] QString value(const QString &name) const { return m_values.now.value(name); }

private:
    void applyToNetwork(DiagramScene &scene, std::size_t index, const interp::RuntimeSnapshot &snapshot, const QString &instance);

    const LdPolicy &m_policy;
    OnlineValues m_values;
    int m_lastCycle = -1;
};

} // namespace iec::editors::ld
