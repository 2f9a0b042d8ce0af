#!/usr/bin/env bash
# Installs what is missing, builds a Release build in build/release and opens IEC Studio on the
# given project (default: the example project). Without a display it runs the project headlessly.
set -euo pipefail
source "$(dirname "$0")/lib.sh"

project=${1:-"$IEC_ROOT/resources/examples/first_steps.xml"}
[ -f "$project" ] || { echo "run.sh: no such project file: $project" >&2; exit 2; }
project=$(cd "$(dirname "$project")" && pwd)/$(basename "$project")

iec_ensure_packages "${IEC_BUILD_PACKAGES[@]}" "${IEC_FONT_PACKAGES[@]}"
build_dir="$IEC_ROOT/build/release"
iec_build "$build_dir" Release -DIEC_BUILD_TESTS=OFF

if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  iec_say "Starting IEC Studio on $project"
  exec "$build_dir/app/iecstudio" "$project"
fi

cli="$build_dir/app/cli/iecstudio-cli"
iec_say "No display (DISPLAY and WAYLAND_DISPLAY are unset): running $project headlessly instead."
iec_say "To see the IDE, run this on a desktop, or under Xvfb: xvfb-run -a scripts/run.sh"
status=0
"$cli" run "$project" --cycles 100 --cycle-time 10ms --watch Main.Count --watch Main.Blink || status=$?
if [ "$status" -eq 2 ]; then
  # The interpreter of this build cannot run projects yet: show what the project holds instead.
  "$cli" info "$project" || "$cli" --help
fi
