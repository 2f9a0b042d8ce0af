#pragma once

#include "app/projecttreemodel.h"
#include "model/body.h"

#include <QIcon>

namespace iec::app {

// Icons of the project tree: a coloured badge with the language's short name for bodies (as the
// IEC language abbreviations are what users know), the style's icons for the other nodes.
QIcon languageIcon(model::BodyLanguage language);
QString languageName(model::BodyLanguage language);
QString languageShortName(model::BodyLanguage language);
QIcon nodeIcon(ProjectTreeModel::NodeKind kind);

} // namespace iec::app
