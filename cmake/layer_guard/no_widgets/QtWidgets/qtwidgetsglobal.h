// Shadows Qt's header for targets below the editors layer (see cmake/IecLayering.cmake).
#error "This layer must not use QtWidgets: only editors/ and app/ may (DESIGN.md)."
