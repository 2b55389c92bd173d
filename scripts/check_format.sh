#!/usr/bin/env bash
# Fails when a tracked C++ source is not formatted as .clang-format says (clang-format 14,
# Debian's clang-format package). Fix with: git ls-files '*.cpp' '*.hpp' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null; then
  echo "check_format: clang-format not found (Debian package clang-format)" >&2
  exit 1
fi
git ls-files -z '*.cpp' '*.hpp' | xargs -0 clang-format --dry-run --Werror
echo "check_format: every tracked source is formatted"
