#include "editors/standardeditors.h"

#include "editors/cfc/cfceditor.h"
#include "editors/cfc/cfcscene.h"
#include "editors/common/editorregistry.h"
#include "editors/fbd/fbdeditor.h"
#include "editors/fbd/fbdscene.h"
#include "editors/ld/ldeditor.h"
#include "editors/ld/ldscene.h"
#include "editors/sfc/sfceditor.h"
#include "editors/sfc/sfcscene.h"

namespace iec::editors {

void registerStandardEditors()
{
    static bool registered = false;
    if (registered)
        return;
    registered = true;
    EditorRegistry &registry = EditorRegistry::instance();
    registry.add({EditorLanguage::SFC,
        [](model::ProjectModel &model, const model::BodyRef &ref, QUndoStack *stack) -> DiagramEditor * {
            return new sfc::SfcEditor(model, ref, stack);
        },
        [] { return std::unique_ptr<DiagramPolicy>(std::make_unique<sfc::SfcPolicy>()); },
        &sfc::newChartBody});
    registry.add({EditorLanguage::LD,
        [](model::ProjectModel &model, const model::BodyRef &ref, QUndoStack *stack) -> DiagramEditor * {
            return new ld::LdEditor(model, ref, stack);
        },
        [] { return std::unique_ptr<DiagramPolicy>(std::make_unique<ld::LdPolicy>()); }});
    registry.add({EditorLanguage::FBD,
        [](model::ProjectModel &model, const model::BodyRef &ref, QUndoStack *stack) -> DiagramEditor * {
            return new fbd::FbdEditor(model, ref, stack);
        },
        [] { return std::unique_ptr<DiagramPolicy>(std::make_unique<fbd::FbdPolicy>()); }});
    registry.add({EditorLanguage::CFC,
        [](model::ProjectModel &model, const model::BodyRef &ref, QUndoStack *stack) -> DiagramEditor * {
            return new cfc::CfcEditor(model, ref, stack);
        },
        [] { return std::unique_ptr<DiagramPolicy>(std::make_unique<cfc::CfcPolicy>()); },
        [] {
            // An FBD body marked as CFC (docs/editors-cfc.md).
            model::Body body = model::Body::withLanguage(model::BodyLanguage::FBD);
            body.addData.push_back({QString::fromLatin1(kIecStudioCfcAddDataName), QStringLiteral("implementation"),
                QStringLiteral("<cfc/>")});
            return body;
        }});
}

} // namespace iec::editors
