#!/usr/bin/env bash
# Installs what is missing, builds a Debug build with AddressSanitizer and UndefinedBehaviorSanitizer
# in build/test, and runs every test. Extra arguments go to ctest (e.g. -R tst_projectmodel).
set -euo pipefail
source "$(dirname "$0")/lib.sh"

iec_ensure_packages "${IEC_BUILD_PACKAGES[@]}" "${IEC_FONT_PACKAGES[@]}" libxml2-utils

build_dir="$IEC_ROOT/build/test"
# Shared project libraries: a hundred statically linked sanitizer builds would fill the disk.
iec_build "$build_dir" Debug -DIEC_SANITIZE=ON -DIEC_SHARED_LIBS=ON

iec_say "Running the tests"
cd "$build_dir"
export QT_QPA_PLATFORM=offscreen
ctest --output-on-failure --parallel "$(nproc)" "$@"
