# Compiler launcher, warnings and the sanitizer switch shared by every target.

find_program(IEC_CCACHE ccache)
if(IEC_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER "${IEC_CCACHE}")
endif()

option(IEC_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)

# The test build links about a hundred executables against the project's libraries. Linked
# statically, each carries its own copy of every library with its sanitizer data and debug
# information (some 600 MB each, 29 GB in all, more than a CI machine's disk may hold); shared,
# each carries only its own code. Release builds keep the static libraries: one self-contained
# executable to ship.
option(IEC_SHARED_LIBS "Build the project's libraries as shared libraries (the test build)" OFF)
if(IEC_SHARED_LIBS)
  set(IEC_LIBRARY_TYPE SHARED)
else()
  set(IEC_LIBRARY_TYPE STATIC)
endif()

add_library(iec_build_settings INTERFACE)
target_compile_options(iec_build_settings INTERFACE -Wall -Wextra -Wpedantic -Wno-unused-parameter -Wno-missing-field-initializers)
target_compile_definitions(iec_build_settings INTERFACE
  QT_NO_FOREACH
  QT_USE_QSTRINGBUILDER)

if(IEC_SANITIZE)
  # -fno-sanitize-recover turns every UBSan finding into a test failure instead of a log line.
  set(_iec_san -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  target_compile_options(iec_build_settings INTERFACE ${_iec_san})
  target_link_options(iec_build_settings INTERFACE ${_iec_san})
endif()

# libFuzzer (clang only; scripts/fuzz.sh configures build/fuzz with it): every library is
# instrumented for coverage, and tests/fuzz builds its targets as fuzzers instead of replayers.
option(IEC_FUZZ "Build the fuzz targets of tests/fuzz with libFuzzer (clang)" OFF)
if(IEC_FUZZ)
  target_compile_options(iec_build_settings INTERFACE -fsanitize=fuzzer-no-link)
endif()
