#pragma once

#include "app/projecttreemodel.h"
#include "editors/common/editorlanguage.h"

#include <QIcon>

namespace iec::app {

// Icons of the project tree: a coloured badge with the language's short name for bodies (as the
// IEC language abbreviations are what users know), the style's icons for the other nodes.
// By the editor language: a CFC is an FBD (or, from CODESYS, an ST) body to the model and a
// language of its own to the user.
QIcon languageIcon(editors::EditorLanguage language);
QString languageName(editors::EditorLanguage language);
QIcon nodeIcon(ProjectTreeModel::NodeKind kind);

} // namespace iec::app
