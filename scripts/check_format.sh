#!/usr/bin/env bash
# Fails when a tracked C++ file is not formatted as .clang-format says (CI runs it; a few
# seconds). Fix with:  git ls-files '*.cpp' '*.hpp' | xargs clang-format -i
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
formatter=$(command -v clang-format || command -v clang-format-14 || true)
[[ -n $formatter ]] || { echo "check_format: clang-format is not installed" >&2; exit 1; }
report=$(mktemp)
trap 'rm -f "$report"' EXIT
if ! git ls-files '*.cpp' '*.hpp' | xargs "$formatter" --dry-run --Werror 2>"$report"; then
  grep -E "(warning|error):" "$report" | cut -d: -f1 | sort -u | sed 's/^/check_format: not formatted: /' >&2
  echo "check_format: fix with: git ls-files '*.cpp' '*.hpp' | xargs clang-format -i" >&2
  exit 1
fi
echo "check_format: $(git ls-files '*.cpp' '*.hpp' | wc -l) files formatted"
