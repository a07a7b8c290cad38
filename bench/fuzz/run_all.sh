#!/usr/bin/env bash
# run_all.sh BUILD_DIR [SECONDS [JOBS]]: every libFuzzer target of tests/fuzz for SECONDS each (default 600),
# JOBS at a time (default 1), seeded as ctest seeds them (after a main build of BUILD_DIR, whose ctest
# wrote the .cnb and .3dm seeds: run `ctest -R 'fuzz.write_cnb_seeds|3dm.generate'` there first). Each
# target's work folder is BUILD_DIR/fuzz-long/<target>; prints each target's executions, coverage and
# corpus figures, and fails if any target found something (its log and inputs are in its folder).
set -euo pipefail
build=$(realpath "$1")
seconds=${2:-600}
jobs=${3:-1}
here=$(cd "$(dirname "$0")/../.." && pwd)
corpus=$here/../shared/corpus
samples=$here/samples
targets=$build/tests/fuzz/targets
runs=(
  "stl stl $corpus/stl $samples"
  "vrml97 wrl $corpus/vrml $samples"
  "x3d_classic x3dv $corpus/vrml $samples"
  "x3d_xml x3d $corpus/vrml $samples"
  "cnb cnb $build/tests/fuzz/cnb_seeds"
  "3dm 3dm $corpus/3dm $build/tests/3dm/generated"
  "step_precheck step,stp $corpus/step $samples"
  "iges_precheck igs,iges $corpus/iges $samples"
)
mkdir -p "$build/fuzz-long"
run_one() {
  set -- $1
  local name=$1 extensions=$2
  shift 2
  if bash "$here/tests/fuzz/run_fuzz.sh" "$targets/fuzz_$name" "$seconds" "$build/fuzz-long/$name" "$extensions" "$@" \
       >"$build/fuzz-long/$name.summary" 2>&1; then
    echo "$name: clean"
  else
    echo "$name: FAILED (see $build/fuzz-long/$name)"
  fi
  grep -E '^stat::(number_of_executed_units|new_units_added|peak_rss_mb)|DONE' "$build/fuzz-long/$name.summary" | sed "s/^/  $name /"
}
export -f run_one
export here targets build seconds
printf '%s\n' "${runs[@]}" | xargs -P "$jobs" -I{} bash -c 'run_one "$@"' _ {} | tee "$build/fuzz-long/summary.txt"
! grep -q FAILED "$build/fuzz-long/summary.txt"
