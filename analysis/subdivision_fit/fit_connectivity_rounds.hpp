#pragma once
// Connectivity moves interleaved with global fits: a sweep of edge swaps and tag toggles
// (improve_control_connectivity), then fit_subdivision_surface on the result, and again while the fits keep
// getting closer. The moves are judged by local re-fits with the rest of the mesh held; a global fit
// after each sweep lets the next sweep judge its moves against settled neighbours. On the corpus's
// motor at 268 control vertices, two sweeps then one fit reached 0.570 of the quadric decimation's
// RMS; one sweep and one fit, four times, 0.543, 0.515, 0.510, 0.508 (stop 32, exp code).
#include <vector>

#include "analysis/subdivision_fit/fit_subdivision_surface.hpp"
#include "analysis/subdivision_fit/improve_control_connectivity.hpp"

namespace cadnurbs {

struct ConnectivityRoundsOptions {
  ConnectivityOptions moves;  // its `sweeps` are per round
  SubdivisionFitOptions fit;         // the global fit after each round's moves
  int max_rounds = 4;
  double min_gain = 0.01;     // another round only after one whose fit lowered the RMS by this share or more
};

struct ConnectivityRoundsReport {
  ConnectivityReport moves;   // summed over the rounds (energy_before: the first round's, energy_after: the last's)
  int rounds = 0;             // rounds whose moves were fitted
  int rounds_kept = 0;        // of those, the ones whose fit beat the fit before it (a round after a worse one is not run)
  std::vector<double> rms;    // each fitted round's RMS at its samples, as SubdivisionFitReport::rms
};

// Takes a welded input mesh, a fitted control mesh and its fit report (fit_subdivision_surface with
// options.fit); returns the control mesh of the closest fit: the given one when no round's fit had a
// lower RMS. Stops after a round that keeps no move (no fit run), a fit that is not closer, a gain
// under min_gain (that fit kept), or max_rounds. `fit_report` gets the returned mesh's fit report,
// its iterations those of all the rounds' fits (0 when none ran).
// Refuses (std::invalid_argument) max_rounds < 1 and what improve_control_connectivity and
// fit_subdivision_surface refuse.
SubdivisionControlMesh fit_connectivity_rounds(const TriangleMesh& input, const SubdivisionControlMesh& fitted,
                                             const SubdivisionFitReport& fitted_report, const ConnectivityRoundsOptions& options,
                                             SubdivisionFitReport* fit_report = nullptr,
                                             ConnectivityRoundsReport* report = nullptr);

}  // namespace cadnurbs
