# Shared by run.sh and test.sh: package installation and the build of one configuration.
# shellcheck shell=bash

IEC_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# What building IEC Studio needs on Debian 12.
IEC_BUILD_PACKAGES=(cmake ninja-build g++ ccache pkg-config
  qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-svg-dev qt6-charts-dev libqt6opengl6-dev qt6-translations-l10n
  libpugixml-dev)
# Fonts for Latin and Chinese text, so the UI and rendered diagrams read in every UI language.
IEC_FONT_PACKAGES=(fonts-dejavu-core fonts-wqy-microhei)

# Relative paths in the compiler cache key, so a fresh clone elsewhere reuses earlier builds.
export CCACHE_BASEDIR="$IEC_ROOT"

iec_say() { printf '\033[1m==> %s\033[0m\n' "$*" >&2; }

# Installs the packages that are not installed yet, with apt-get as root or through sudo.
iec_ensure_packages() {
  local missing=()
  local package
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' || missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  iec_say "Installing ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "Please install as root: ${missing[*]}" >&2; return 1; }
    sudo=(sudo)
  fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# iec_build DIR BUILD_TYPE [extra cmake arguments...]: configures once, then builds incrementally.
# The extra arguments are applied to an existing tree too, so a tree configured before an option
# was added to a script picks it up.
iec_build() {
  local dir=$1 type=$2
  shift 2
  if [ ! -f "$dir/build.ninja" ]; then
    iec_say "Configuring $type build in $dir"
    cmake -S "$IEC_ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$type" "$@"
  elif [ $# -gt 0 ]; then
    cmake -S "$IEC_ROOT" -B "$dir" "$@" >/dev/null
  fi
  iec_say "Building in $dir"
  cmake --build "$dir" --parallel "$(nproc)"
}
