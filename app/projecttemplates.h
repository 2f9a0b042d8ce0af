#pragma once

#include "editors/common/editorlanguage.h"
#include "model/project.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace iec::app {

// File → New: what a new project starts from. Every template but Empty has one program "Main"
// in its language, run by the cyclic task "MainTask" (T#10ms) of resource "Resource" in
// configuration "Config", as the shipped examples are laid out.
enum class ProjectTemplate { Empty, ST, LD, FBD, CFC, SFC, IL };

class ProjectTemplates
{
    Q_DECLARE_TR_FUNCTIONS(iec::app::ProjectTemplates)

public:
    [[nodiscard]] static QList<ProjectTemplate> all();
    [[nodiscard]] static QString name(ProjectTemplate projectTemplate);
    [[nodiscard]] static QString description(ProjectTemplate projectTemplate);
    // The project; it compiles without errors. LD has one rung (Start closes Lamp), SFC an
    // initial step, the others an empty body.
    [[nodiscard]] static model::Project create(ProjectTemplate projectTemplate);
};

// The addData entry a body gets when it was made as CFC: an FBD body drawn freely
// (docs/editors-cfc.md).
inline constexpr const char *kCfcBodyAddDataName = editors::kIecStudioCfcAddDataName;

// The program a project shows first: the type of the first program instance of the first task
// (of the first resource of the first configuration), else the program a project without
// configuration runs; empty when there is none.
[[nodiscard]] QString mainProgramName(const model::Project &project);

} // namespace iec::app
