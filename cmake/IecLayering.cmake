# Enforces the layering of DESIGN.md at compile time.
#
# Qt's imported targets put the common qt6 include root on the path, so a Core-only target could
# still write `#include <QtWidgets/QWidget>` and compile. Every QtWidgets/QtGui header starts by
# including its module's *global.h; `layer_guard/` shadows those headers with ones that stop the
# build, and goes first on the include path of the targets that must stay free of them.
set(IEC_LAYER_GUARD_DIR "${CMAKE_CURRENT_LIST_DIR}/layer_guard")

# For iec_model and iec_interpreter: QtCore only.
function(iec_forbid_gui target)
  target_include_directories(${target} BEFORE PRIVATE "${IEC_LAYER_GUARD_DIR}/no_gui")
endfunction()

# For iec_model_undo: QtGui (QUndoStack) but no widgets.
function(iec_forbid_widgets target)
  target_include_directories(${target} BEFORE PRIVATE "${IEC_LAYER_GUARD_DIR}/no_widgets")
endfunction()
