#pragma once

#include "editors/text/textlanguage.h"

#include <QStringList>

class QMimeData;

// A call of a function or function block as text, and the drag that carries one (the library
// pane drags these; the text editors drop them, the diagram editors read the POU's name).
namespace iec::editors {

// The MIME types of a dragged POU: its name (UTF-8) for any editor, and the call ready to insert
// in ST and in IL. text/plain carries the ST call for editors outside IEC Studio.
inline constexpr const char *kPouMimeType = "application/x-iecstudio-pou";
inline constexpr const char *kStCallMimeType = "application/x-iecstudio-call-st";
inline constexpr const char *kIlCallMimeType = "application/x-iecstudio-call-il";

struct CallSignature {
    QString name;
    bool functionBlock = false;
    QStringList inputs;  // inputs and in-outs, in order
    QStringList outputs; // function blocks' outputs
};

// The call with named parameters: ST `LIMIT(MN := , IN := , MX := )` and
// `TON_1(IN := , PT := , Q => , ET => );` (an instance named after the block, to declare with
// Shift+F2); IL `LIMIT(MN := , IN := , MX := )` and `CAL TON_1(IN := , PT := )`.
[[nodiscard]] QString callText(TextLanguage language, const CallSignature &signature);
// The drag of a POU: every MIME type above. The caller owns the result.
[[nodiscard]] QMimeData *pouMimeData(const CallSignature &signature);
[[nodiscard]] QString mimeCallMimeType(TextLanguage language);

} // namespace iec::editors
