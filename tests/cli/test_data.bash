# Sourced by the CLI and GUI tests that read the project's test data: tests/data/shared (the
# files that travel with the repository, tests/data/shared/SOURCES.md), then the optional full
# collection ../shared/data beside the repository (the same layout). tests/test_data.h is the
# C++ side. A test that needs a file neither place has is skipped (exit 77, one line naming it).
_data_repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
_data_missing=""

# data_path REL: prints where REL (relative to the data root) is; prints nothing and returns 1
# when neither place has it.
data_path() {
  local root
  for root in "$_data_repo/tests/data/shared" "$_data_repo/../shared/data"; do
    if [ -e "$root/$1" ]; then printf '%s\n' "$root/$1"; return 0; fi
  done
  return 1
}

# data_dir REL: the folder REL for a test that walks it whole: ../shared/data's when that is
# present (it holds more files), else the repository's.
data_dir() {
  if [ -d "$_data_repo/../shared/data" ]; then printf '%s\n' "$_data_repo/../shared/data/$1"
  else printf '%s\n' "$_data_repo/tests/data/shared/$1"; fi
}

# need_data REL...: the whole test needs these; skip it now (exit 77) naming the first missing.
need_data() {
  local rel
  for rel; do
    data_path "$rel" >/dev/null ||
      { echo "skipped: needs $rel from ../shared/data (not in this checkout; see README, Test data)"; exit 77; }
  done
}

# want_data REL: a part of the test needs REL. Returns 1 when it is missing (the caller leaves
# that part out) and remembers it for data_exit.
want_data() {
  data_path "$1" >/dev/null && return 0
  _data_missing+="${_data_missing:+, }$1"
  return 1
}

# data_exit FAILED: ends the test: 1 when FAILED > 0; else 77 with one line naming what was left
# out when want_data found something missing (ctest counts it as skipped); else 0.
data_exit() {
  [ "$1" -gt 0 ] && exit 1
  if [ -n "$_data_missing" ]; then
    echo "skipped in part: needs $_data_missing from ../shared/data (not in this checkout; see README, Test data)"
    exit 77
  fi
  exit 0
}
