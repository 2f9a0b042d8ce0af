#pragma once

#include "editors/text/standardlibrary.h"

namespace iec::editors {

// The CoDeSys 2.3 Util library and Beremiz's RTC and LOGGER as the editors offer them (library
// pane, input assistant, completion, the pins of a box in LD, FBD and CFC). Their pins are read
// from the interpreter's own definitions (interp::utilLibrary()), so what the editors show is
// what the compiler accepts; this adds each block's library, category and description.
[[nodiscard]] QList<StdPou> utilLibraryPous();

} // namespace iec::editors
