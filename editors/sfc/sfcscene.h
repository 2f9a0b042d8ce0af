#pragma once

#include "editors/common/diagramscene.h"

namespace iec::editors::sfc {

// The SFC policy of the shared scene: one item per element, the wires between them, and the
// level shown (the chart itself, or the inside of a macro step, by the path of macro localIds).
// Imported charts keep the positions of the tool that drew them until the user edits the chart.
class SfcPolicy : public DiagramPolicy
{
public:
    const std::vector<model::Element> *elements(const model::ProjectModel &model, const model::BodyRef &ref) const override;
    void populate(DiagramScene &scene, const std::vector<model::Element> &elements) override;

    [[nodiscard]] const std::vector<quint64> &macroPath() const { return m_macroPath; }
    void setMacroPath(std::vector<quint64> path) { m_macroPath = std::move(path); }

private:
    std::vector<quint64> m_macroPath;
    // A chart whose positions were generated on import (CODESYS/TwinCAT write none) is shown in
    // the editor's own layout; the model gets it with the first edit.
    mutable std::vector<model::Element> m_display;
};

// The elements of a level: `path` leads through macro steps from the top level. nullptr when
// the path does not lead anywhere (a macro step was deleted).
const std::vector<model::Element> *levelElements(const std::vector<model::Element> &top, const std::vector<quint64> &path);
// The top level's elements with the level at `path` replaced by `level`.
std::vector<model::Element> withLevel(
    std::vector<model::Element> top, const std::vector<quint64> &path, std::vector<model::Element> level);

} // namespace iec::editors::sfc
