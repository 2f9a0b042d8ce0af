#pragma once

#include "app/textrename.h"
#include "model/body.h"
#include "model/ids.h"
#include "model/pou.h"

#include <functional>
#include <optional>
#include <vector>

class QUndoCommand;

namespace iec::model {
class ProjectModel;
}

// One rewrite (of names, for a rename) applied alike to the text of ST/IL bodies, to the
// expressions of graphical elements and to the elements themselves, turned into the model's
// undo commands.
namespace iec::app {

using TextRewrite = std::function<QString(const QString &, TextDialect)>;
using ElementRewrite = std::function<bool(model::Element &, const std::vector<model::Element> &siblings)>;

struct BodyRewrite {
    TextRewrite text;
    ElementRewrite element;
    // Whether `text` also applies to the expressions of graphical elements (variables, contacts,
    // coils, inline SFC conditions and actions); names of actions and transitions are not there.
    bool inGraphics = true;
};

// Adds under `parent` one command per changed element or text body: the POU's body and the
// bodies of its actions and transitions; `skip` is left alone.
void addPouRewrite(model::ProjectModel &model, const model::Pou &pou, const BodyRewrite &rewrite,
    QUndoCommand *parent, const std::optional<model::BodyRef> &skip = {});

// Several rewrites of the same bodies as one (one command per body, applied in order).
[[nodiscard]] BodyRewrite composed(std::vector<BodyRewrite> rewrites);

} // namespace iec::app
