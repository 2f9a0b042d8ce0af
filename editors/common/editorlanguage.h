#pragma once

#include <QString>

namespace iec::model {
struct Body;
enum class BodyLanguage;
}

namespace iec::editors {

// The language an editor is chosen by. It is finer than model::BodyLanguage: a CFC diagram is
// stored as FBD (or, by CODESYS, in the addData of an empty ST body) and needs its own editor.
enum class EditorLanguage { ST, IL, LD, FBD, CFC, SFC };

// The one place that decides which editor a body gets.
EditorLanguage editorLanguage(const model::Body &body);
// "ST", "IL", "LD", "FBD", "CFC", "SFC" (the languages' names are the same in every UI language).
QString editorLanguageName(EditorLanguage language);
// The body language a new body of this editor language is stored in (CFC: FBD).
model::BodyLanguage storedLanguage(EditorLanguage language);
// The marker of a CODESYS CFC diagram: an addData entry whose name ends like this.
inline constexpr const char *kCodesysCfcAddDataSuffix = "/plcopenxml/cfc";
// The marker of a CFC made in IEC Studio: an FBD body (Beremiz opens it as one, with the same
// drawing and order) that carries an addData entry of this name.
inline constexpr const char *kIecStudioCfcAddDataName = "http://www.iecstudio.org/cfc";

} // namespace iec::editors
