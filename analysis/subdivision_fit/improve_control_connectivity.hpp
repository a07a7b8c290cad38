#pragma once
// Better connectivity for a fitted Loop control mesh at a fixed vertex count (Hoppe et al. 1994,
// "Piecewise smooth surface reconstruction", phase 3, without the collapses and splits that change
// the count): legal edge swaps, corner-tag toggles and crease-tag toggles, each judged by a local
// re-fit of the control points whose limit patches it changes, and kept when the local energy
// (squared distances both ways + spring) drops.
#include "analysis/subdivision_fit/fit_subdivision_surface.hpp"

namespace cadnurbs {

struct ConnectivityOptions {
  int levels = 3;               // refinements that stand for the limit surface (as the fit's)
  int sweeps = 2;               // passes over all candidate moves
  int local_rounds = 2;         // project-and-solve rounds of each local re-fit
  int free_rings = 0;           // control points re-fitted: the changed vertices and this many rings around
  double fairness = 1e-5;       // spring weight relative to the data (as SubdivisionFitOptions)
  double tangent_weight = 0.001; // point-to-point share next to the tangent-plane distance (as SubdivisionFitOptions)
  bool swaps = true, corner_toggles = true, crease_toggles = true;
};

struct ConnectivityReport {
  int candidates = 0;  // local re-fits run
  int swaps = 0, corner_toggles = 0, crease_toggles = 0;  // moves kept
  double energy_before = 0, energy_after = 0;             // sum of squared distances at the samples
};

// Takes a welded input mesh and a fitted control mesh (fit_subdivision_surface); returns a control mesh with
// as many vertices whose connectivity and tags were changed where that lowered the local energy, and
// whose moved control points are the local re-fits' (run fit_subdivision_surface on it for a global fit).
// A swap is legal on an interior untagged edge whose ends keep 3 edges or more, whose opposite
// vertices are not already joined, and whose new triangles do not turn against the old ones; a corner
// tag toggles only on a vertex with two sharp edges (or a tagged one); a crease tag on any interior
// edge. Each sweep tries every swap, then every corner toggle, then every crease toggle, once, and
// keeps a move when it lowers the local energy by 0.01 % or more; no more sweeps after one that keeps
// none.
// Cost: every try builds the limit map of its region only (limit_patches), but projects the
// region's samples both ways in each of its rounds (one before, local_rounds + 1 after), and the
// projections are most of the time: on the corpus's tray, 200 control vertices, 2,291 tries took
// about 1,000 s of CPU on a loaded machine, some 15 plain fits; so fit-loop runs it on request only.
// Refuses (std::invalid_argument) an input or control mesh without triangles, levels outside 1..5.
SubdivisionControlMesh improve_control_connectivity(const TriangleMesh& input, const SubdivisionControlMesh& fitted,
                                             const ConnectivityOptions& options, ConnectivityReport* report = nullptr);

}  // namespace cadnurbs
