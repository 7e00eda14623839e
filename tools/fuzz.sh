#!/usr/bin/env bash
# `make fuzz`: every libFuzzer harness of tests/fuzz for SECONDS each (ASan + UBSan, clang),
# on a working copy of its seed corpus with its dictionary, so what the fuzzer adds stays in the
# build tree. A crash, leak, timeout (10 s on one input) or out-of-memory (2 GB) fails the run;
# its input is kept as build-fuzz/artifacts/<parser>/crash-* and named on the last line.
# usage: tools/fuzz.sh [SECONDS] [PARSER...]     (default 60 s, every harness)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift || true
build=${FUZZ_BUILD:-$root/build-fuzz}
jobs=$(nproc)

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHAZE_FUZZ=ON \
        -DHAZE_BUILD_GL=OFF -DHAZE_BUILD_GUI=OFF -DCMAKE_C_COMPILER=clang-14 \
        -DCMAKE_CXX_COMPILER=clang++-14 "${launcher[@]}" >/dev/null
fi

parsers=("$@")
if [ ${#parsers[@]} -eq 0 ]; then
  for src in "$root"/tests/fuzz/*_fuzz.cpp; do
    stem=$(basename "$src" .cpp)
    parsers+=("${stem%_fuzz}")
  done
fi
targets=()
for p in "${parsers[@]}"; do targets+=("fuzz_$p"); done
cmake --build "$build" -j "$jobs" --target "${targets[@]}"

failed=()
printf '%-14s %12s %10s %8s\n' harness executions exec/s corpus
for p in "${parsers[@]}"; do
  work=$build/corpus-work/$p
  artifacts=$build/artifacts/$p
  mkdir -p "$work" "$artifacts"
  dict=()
  [ -f "$root/tests/fuzz/dict/$p.dict" ] && dict=(-dict="$root/tests/fuzz/dict/$p.dict")
  log=$build/fuzz-$p.log
  # The seed folder is read-only input: libFuzzer writes only into the first folder.
  if ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1 \
     LSAN_OPTIONS=suppressions="$root/tests/fuzz/lsan.supp" \
     "$build/tests/fuzz_$p" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
       -print_final_stats=1 -artifact_prefix="$artifacts/" "${dict[@]}" \
       "$work" "$root/tests/fuzz/corpus/$p" >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    size=$(find "$work" -type f | wc -l)
    printf '%-14s %12s %10s %8s\n' "$p" "${runs:-?}" "${rate:-?}" "$size"
  else
    printf '%-14s %12s\n' "$p" FAILED
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$log" | head -5 || true
    failed+=("$p ($(ls "$artifacts" | head -1), log $log)")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: FAILED: ${failed[*]}"
  exit 1
fi
echo "fuzz: ${#parsers[@]} harnesses ran ${seconds} s each; nothing found"
