#!/usr/bin/env bash
# scripts/fuzz.sh TARGET [SECONDS] [libFuzzer options...]
#   Builds the fuzz target fuzz_TARGET (tests/fuzz/fuzz_TARGET.cpp) with clang, libFuzzer,
#   AddressSanitizer and UndefinedBehaviorSanitizer in build/fuzz, installing clang and its
#   runtime when they are missing, and runs it for SECONDS (default 60) on its corpus: the inputs
#   it found before (build/fuzz/corpus/TARGET), its seeds and the inputs that once made it fail
#   (tests/fuzz/regressions/TARGET). What fails is saved in build/fuzz/crashes/TARGET/: fix it and
#   copy the input to tests/fuzz/regressions/TARGET/, and every ctest run replays it from then on.
# scripts/fuzz.sh --list   prints the targets.
# scripts/fuzz.sh --all [SECONDS] [libFuzzer options...]   runs every target for SECONDS each
#   (default 8: a short check, under a minute in all) and fails when one of them fails.
# scripts/fuzz.sh --check   what .ci/run does: every target for a fixed number of executions
#   (kCheckRuns below, a few seconds each) with -seed=1 on a fresh corpus, so a clean clone
#   explores the same inputs on every machine, however fast, and a failure replays.
# IEC_FUZZ_CORPUS=DIR keeps the corpus in DIR instead of build/fuzz/corpus/TARGET.
# IEC_FUZZ_JOBS=N runs N fuzzers at once (default 1); IEC_BUILD_WRAP is put before the build
# command (e.g. "flock /tmp/build.lock" on a machine where builds take turns).
set -euo pipefail
source "$(dirname "$0")/lib.sh"

targets=$(sed -n 's/^iec_add_fuzz_target(\([a-z_]*\).*/\1/p' "$IEC_ROOT/tests/fuzz/CMakeLists.txt")
if [ "${1:-}" = "--list" ]; then
  echo "$targets"
  exit 0
fi
if [ "${1:-}" = "--check" ]; then
  # Executions per target: about five seconds each on a 2-core CI machine. A time cap alone
  # made a faster machine explore further than the run that was checked before landing.
  declare -A kCheckRuns=([plcopen]=4000 [iectext]=300 [compile]=500 [il]=700 [declarations]=1500 \
    [typetext]=2000 [values]=300000)
  for target in $targets; do
    fresh=$(mktemp -d)
    IEC_FUZZ_CORPUS=$fresh "$0" "$target" 120 -seed=1 -runs="${kCheckRuns[$target]:-10000}"
    rm -rf "$fresh"
  done
  exit 0
fi
if [ "${1:-}" = "--all" ]; then
  seconds=${2:-8}
  shift $(($# >= 2 ? 2 : 1))
  for target in $targets; do
    "$0" "$target" "$seconds" "$@"
  done
  exit 0
fi
target=${1:?"usage: scripts/fuzz.sh TARGET [SECONDS] [libFuzzer options...] (scripts/fuzz.sh --list)"}
seconds=${2:-60}
shift $(($# >= 2 ? 2 : 1))
if ! grep -qx "$target" <<<"$targets"; then
  echo "Unknown fuzz target '$target'; the targets are:" $targets >&2
  exit 2
fi

iec_ensure_packages "${IEC_BUILD_PACKAGES[@]}" clang-14 libclang-rt-14-dev libxml2-utils

dir="$IEC_ROOT/build/fuzz"
if [ ! -f "$dir/build.ninja" ]; then
  iec_say "Configuring the fuzz build in $dir"
  # -O1 keeps executions fast; assertions stay on (no NDEBUG): they are what the fuzzer looks for.
  CC=clang-14 CXX=clang++-14 cmake -S "$IEC_ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" -DIEC_SANITIZE=ON -DIEC_FUZZ=ON -DIEC_BUILD_BENCH=OFF
fi
iec_say "Building fuzz_$target"
# shellcheck disable=SC2086 # IEC_BUILD_WRAP is a command with its arguments
${IEC_BUILD_WRAP:-} cmake --build "$dir" --target "fuzz_$target" --parallel "$(nproc)"

corpus="${IEC_FUZZ_CORPUS:-$dir/corpus/$target}"
crashes="$dir/crashes/$target"
mkdir -p "$corpus" "$crashes"
read -r -a seeds <"$dir/tests/fuzz/fuzz_$target.seeds"
inputs=("$corpus")
for folder in "${seeds[@]}" "$IEC_ROOT/tests/fuzz/regressions/$target"; do
  [ -d "$folder" ] && inputs+=("$folder")
done

iec_say "Fuzzing $target for ${seconds}s (corpus $corpus, failures to $crashes)"
export QT_QPA_PLATFORM=offscreen
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$IEC_ROOT/tests/lsan.supp:print_suppressions=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
parallel=()
if [ "${IEC_FUZZ_JOBS:-1}" -gt 1 ]; then
  parallel=(-jobs="$IEC_FUZZ_JOBS" -workers="$IEC_FUZZ_JOBS")
fi
nice -n 10 "$dir/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 \
  -max_len=65536 -print_final_stats=1 -artifact_prefix="$crashes/" "${parallel[@]}" "$@" "${inputs[@]}"
