#!/usr/bin/env bash
# run_fuzz.sh TARGET SECONDS WORK_DIR EXTENSIONS SEED...
#   TARGET      a libFuzzer executable of tests/fuzz/targets (built by the main build)
#   SECONDS     how long to fuzz
#   WORK_DIR    emptied, then holds seeds/ (links), corpus/ (new inputs), artifacts/ (findings), fuzz.log
#   EXTENSIONS  comma-separated, case-insensitive: which files of the SEED folders are seeds (stl,wrl,...)
#   SEED        folders or files, read only
# First runs TARGET over the regression files of tests/fuzz/regressions/<target name without fuzz_>/ (inputs
# an earlier run found), then fuzzes for SECONDS. Fails on any crash, sanitizer report, input slower than
# 10 s, or RSS above 1 GB; prints libFuzzer's final figures (executions, coverage) either way.
set -euo pipefail
[ $# -ge 5 ] || { echo "usage: run_fuzz.sh TARGET SECONDS WORK_DIR EXTENSIONS SEED..." >&2; exit 2; }
target=$1 seconds=$2 work=$3 extensions=$4
shift 4
[ -x "$target" ] || { echo "run_fuzz.sh: $target was not built (the fuzz targets need clang++ and libclang-rt-14-dev, which scripts/setup.sh installs)" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work/seeds" "$work/corpus" "$work/artifacts"
is_seed() {
  local ext=${1##*.}
  [[ ",${extensions,,}," == *",${ext,,},"* ]]
}
for seed in "$@"; do
  if [ -d "$seed" ]; then files=("$seed"/*); else files=("$seed"); fi
  for file in "${files[@]}"; do
    [ -f "$file" ] && is_seed "$file" && ln -sf "$(realpath "$file")" "$work/seeds/$(basename "$(dirname "$file")")-$(basename "$file")"
  done
done
[ -n "$(ls "$work/seeds")" ] || { echo "run_fuzz.sh: no .{$extensions} seed in $*" >&2; exit 1; }

export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
limits=(-rss_limit_mb=1024 -malloc_limit_mb=1024 -timeout=10)
name=$(basename "$target")
regressions=$(dirname "$(realpath "$0")")/regressions/${name#fuzz_}
if [ -d "$regressions" ]; then
  "$target" "${limits[@]}" "$regressions"/* >"$work/regressions.log" 2>&1 \
    || { echo "run_fuzz.sh: $name fails on a regression file of $regressions" >&2; tail -40 "$work/regressions.log" >&2; exit 1; }
  echo "regression files passed: $(ls "$regressions" | wc -l)"
fi

status=0
"$target" -max_total_time="$seconds" -max_len=262144 "${limits[@]}" -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/corpus" "$work/seeds" >"$work/fuzz.log" 2>&1 || status=$?
grep -E '^(stat::|Done |INFO: seed corpus)|ERROR|SUMMARY|==[0-9]+==|runtime error|Test unit written' "$work/fuzz.log" | head -60
grep -E '^#[0-9]+.*(DONE|pulse)' "$work/fuzz.log" | tail -1
if [ $status -ne 0 ]; then
  echo "run_fuzz.sh: $name failed (exit $status); log $work/fuzz.log, inputs in $work/artifacts" >&2
  tail -40 "$work/fuzz.log" >&2
fi
exit $status
