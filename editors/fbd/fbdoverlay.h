#pragma once

#include "editors/common/overlaymapper.h"

#include <QHash>

namespace iec::editors::fbd {

class FbdPolicy;

// The online overlay of a function block diagram: each variable's value after its name, the
// values at the pins of boxes, TRUE lines thick and blue (FALSE black, as in LD), forced values
// marked. Only the networks a view shows are restyled; the editor applies the snapshot again when
// the view scrolls.
class FbdOverlayMapper : public OverlayMapper
{
public:
    explicit FbdOverlayMapper(const FbdPolicy &policy);

    QStringList names(const DiagramScene &scene, const QString &instance) const override;
    void apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance) override;
    void clear(DiagramScene &scene) override;

    // The name the runtime knows a variable or assignment by, empty for other elements and for
    // constants.
    [[nodiscard]] QString variableName(quint64 localId, const QString &instance) const;
    [[nodiscard]] QString value(const QString &name) const { return m_values.value(name); }

private:
    void applyToNetwork(DiagramScene &scene, std::size_t index, const interp::RuntimeSnapshot &snapshot, const QString &instance);

    const FbdPolicy &m_policy;
    QHash<QString, QString> m_values;
};

} // namespace iec::editors::fbd
