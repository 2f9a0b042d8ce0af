# Compiler launcher, warnings and the sanitizer switch shared by every target.

find_program(IEC_CCACHE ccache)
if(IEC_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER "${IEC_CCACHE}")
endif()

option(IEC_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)

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
