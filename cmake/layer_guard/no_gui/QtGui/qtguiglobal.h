// Shadows Qt's header for targets that must stay GUI-free (see cmake/IecLayering.cmake).
#error "This layer must not use QtGui: the model and the interpreter depend on QtCore only (DESIGN.md)."
