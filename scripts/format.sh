#!/usr/bin/env bash
# Formats the C++ sources with .clang-format. `scripts/format.sh --check` only reports.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=(-i)
[ "${1:-}" = "--check" ] && mode=(--dry-run --Werror)
git ls-files '*.cpp' '*.h' | xargs -r clang-format "${mode[@]}"
