#!/usr/bin/env bash
# Writes, for every bundled capping, our own tessellation of the committed sample files, and the
# swept body alone with its tessellation (for view3dscene, which ignores trimming).
#   make_sample_meshes.sh CADNURBS SAMPLES_DIR OUT_DIR
set -euo pipefail
cadnurbs=$1 samples=$2 out=$3
mkdir -p "$out"
for shape in capping-90 capping-end capping-post capping-moulded; do
  "$cadnurbs" convert "$samples/$shape.x3dv" -o "$out/$shape-mesh.x3dv" --steps 16
  "$cadnurbs" convert "$samples/$shape.wrl" -o "$out/$shape-mesh.wrl" --steps 16
  "$cadnurbs" capping --shape "$shape" --without-lids -o "$out/$shape-body.x3dv"
  "$cadnurbs" convert "$out/$shape-body.x3dv" -o "$out/$shape-body-mesh.x3dv" --steps 16
done
# STEP in (issue 3): the capping's STEP sample and a corpus part with holes, converted to trimmed
# NURBS (.x3dv NurbsTrimmedSurface, .wrl TrimmedSurface through our PROTOs) and to a mesh.
shared=$(cd "$samples/../../shared" && pwd)
for input in "$samples/capping-90.step" "$shared/corpus/step/featuretype.STEP"; do
  name=$(basename "${input%.*}")
  for ext in x3dv wrl; do
    "$cadnurbs" convert "$input" -o "$out/$name-step.$ext"
    "$cadnurbs" convert "$input" -o "$out/$name-step-mesh.$ext" --mesh
  done
done
