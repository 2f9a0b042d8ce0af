#pragma once

#include <QStringList>

namespace iec::editors {

// Comment or uncomment lines the CODESYS V2.3 way, with (* ... *) on each line (V2.3 has no //).
// When every non-blank line is already a whole-line comment, the comment marks are removed;
// otherwise each non-blank line is wrapped after its indentation. Blank lines stay as they are.
[[nodiscard]] QStringList toggleLineComments(const QStringList &lines);

} // namespace iec::editors
