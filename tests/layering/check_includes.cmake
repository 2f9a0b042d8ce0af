# cmake -DROOT=<repo> -P check_includes.cmake
# Fails when a layer includes a header of a layer above it (DESIGN.md: dependencies only point down).
set(_rules
  "model:interpreter/|editors/|app/"
  "interpreter:editors/|app/"
  "editors:app/")
set(_violations "")
foreach(_rule IN LISTS _rules)
  string(REPLACE ":" ";" _parts "${_rule}")
  list(GET _parts 0 _layer)
  list(GET _parts 1 _forbidden)
  file(GLOB_RECURSE _files "${ROOT}/${_layer}/*.h" "${ROOT}/${_layer}/*.cpp")
  foreach(_file IN LISTS _files)
    file(STRINGS "${_file}" _lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<](${_forbidden})")
    foreach(_line IN LISTS _lines)
      file(RELATIVE_PATH _relative "${ROOT}" "${_file}")
      list(APPEND _violations "${_relative}: ${_line}")
    endforeach()
  endforeach()
endforeach()
if(_violations)
  list(JOIN _violations "\n  " _text)
  message(FATAL_ERROR "Includes that point up the layers:\n  ${_text}")
endif()
message(STATUS "layering: no include points up the layers")
