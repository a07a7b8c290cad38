#!/usr/bin/env bash
# Makes formats/cnb/cnb_coder_prior_table.inc, the coder prior of .cnb format version 4, from the payloads
# of 14 corpus parts (none of them in the part library the benchmarks measure), each converted at
# D = 1 mm and D = 0.01 mm. The table is part of the format: a new one needs a new format version, so
# this is run once per version, with the build of the version before it.
#
#   bench/cnb_coder_prior.sh BUILD_DIR   # BUILD_DIR configured with -DCADNURBS_BENCH=ON and built
set -euo pipefail
build=${1:?usage: bench/cnb_coder_prior.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
corpus=${CADNURBS_CORPUS:-$root/../shared/corpus}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
training=(
  step/as1-tu-203.stp step/as1_pe_203.stp step/dm1-id-214.stp step/io1-tu-203.stp step/io1-cm-214.stp
  step/screw.step step/splinecage.stp step/featuretype.STEP step/goteborg.step step/base_interface_AP203.STEP
  iges/Cube_10x10.igs iges/side.iges iges/wing.iges iges/DTMB-5415_bulbous_bow.iges
)
for part in "${training[@]}"; do
  for d in 1 0.01; do
    "$build/converters/cadnurbs" convert "$corpus/$part" -o "$work/$(basename "$part").$d.cnb" --deviation "$d" \
      >/dev/null 2>&1 || { echo "cnb_coder_prior.sh: converting $part at D = $d failed" >&2; exit 1; }
  done
done
"$build/bench/cnb_coder_prior" table "$work"/*.cnb > "$root/formats/cnb/cnb_coder_prior_table.inc"
echo "wrote formats/cnb/cnb_coder_prior_table.inc from ${#training[@]} parts at 2 deviations"
