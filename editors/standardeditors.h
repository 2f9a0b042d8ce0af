#pragma once

namespace iec::editors {

// Puts every graphical editor of this build into EditorRegistry::instance() (once; later calls
// do nothing). An explicit call, because static libraries drop objects that only register
// themselves: the app's document area and `iecstudio-cli render` call it.
void registerStandardEditors();

} // namespace iec::editors
