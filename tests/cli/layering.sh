#!/usr/bin/env bash
# The layering rule (tools/library_rules.cmake) is enforced and documented as built:
# 1. a configuration with a planted upward link (haze_shows -> haze_renderer) fails, naming it;
# 2. so does a pure library reaching GL (haze_fixtures -> haze_gl);
# 3. so does a link that the layers allow but the folders do not (shows/ -> renderer/);
# 4. docs/architecture.md's "Layers" block lists exactly the layers and folders the check uses.
set -euo pipefail
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

plant() {  # FROM TO EXPECTED-MESSAGE
  if cmake -S "$root" -B "$work/$1-$2" -G Ninja -DHAZE_BUILD_TESTS=OFF -DHAZE_BUILD_GUI=OFF \
       -DHAZE_PLANTED_LINK="$1;$2" >"$work/out-$1" 2>&1; then
    echo "FAIL: configuring with a planted link $1 -> $2 succeeded"
    exit 1
  fi
  if ! grep -qF "$3" "$work/out-$1"; then
    echo "FAIL: the planted link $1 -> $2 failed without naming it; cmake said:"
    tail -20 "$work/out-$1"
    exit 1
  fi
  echo "ok: $1 -> $2 refused: $(grep -F "$3" "$work/out-$1" | head -1 | sed 's/^ *//')"
}
plant haze_shows haze_renderer "library rule broken: haze_shows -> haze_renderer"
plant haze_fixtures haze_gl "library rule broken: haze_fixtures -> haze_gl"
# Allowed by the layers (5 -> 4), refused by the folders: shows/ must not reach into renderer/.
plant haze_frame haze_reference "library rule broken: haze_frame -> haze_reference (shows/ must not link"

# The layers as the check has them, one line each, and as the doc states them.
from_cmake=$(sed -n '/^set(HAZE_LAYERS/,/)$/p' "$root/tools/library_rules.cmake" | grep -o '"[^"]*"' | tr -d '"')
from_doc=$(sed -n '/^<!-- layers -->/,/^<!-- \/layers -->/p' "$root/docs/architecture.md" |
           grep -E '^[0-9]+\. ' | sed -E 's/^[0-9]+\. //; s/`//g; s/,//g')
if [ -z "$from_doc" ] || [ "$from_cmake" != "$from_doc" ]; then
  echo "FAIL: docs/architecture.md's layers differ from tools/library_rules.cmake's HAZE_LAYERS"
  diff <(echo "$from_cmake") <(echo "$from_doc") || true
  exit 1
fi
echo "ok: docs/architecture.md lists the $(echo "$from_cmake" | wc -l) layers the check enforces"

from_cmake=$(sed -n 's/^set(HAZE_FOLDERS \(.*\))$/\1/p' "$root/tools/library_rules.cmake")
from_doc=$(sed -n 's/^Folders, in order: `\(.*\)`\.$/\1/p' "$root/docs/architecture.md")
if [ -z "$from_doc" ] || [ "$from_cmake" != "$from_doc" ]; then
  echo "FAIL: docs/architecture.md's folder order ('$from_doc') differs from HAZE_FOLDERS ('$from_cmake')"
  exit 1
fi
echo "ok: docs/architecture.md states the folder order the check enforces: $from_cmake"
