#include "analysis/subdivision_fit/fit_connectivity_rounds.hpp"

#include <stdexcept>

namespace cadnurbs {

SubdivisionControlMesh fit_connectivity_rounds(const TriangleMesh& input, const SubdivisionControlMesh& fitted,
                                             const SubdivisionFitReport& fitted_report, const ConnectivityRoundsOptions& options,
                                             SubdivisionFitReport* fit_report, ConnectivityRoundsReport* report) {
  if (options.max_rounds < 1) throw std::invalid_argument("fit_connectivity_rounds: max_rounds must be 1 or more");
  SubdivisionControlMesh best = fitted;
  SubdivisionFitReport best_fit = fitted_report;
  ConnectivityRoundsReport rounds;
  int iterations = 0;
  for (int round = 0; round < options.max_rounds; ++round) {
    ConnectivityReport moves;
    const SubdivisionControlMesh moved = improve_control_connectivity(input, best, options.moves, &moves);
    rounds.moves.candidates += moves.candidates;
    rounds.moves.swaps += moves.swaps;
    rounds.moves.corner_toggles += moves.corner_toggles;
    rounds.moves.crease_toggles += moves.crease_toggles;
    if (round == 0) rounds.moves.energy_before = moves.energy_before;
    rounds.moves.energy_after = moves.energy_after;
    if (moves.swaps + moves.corner_toggles + moves.crease_toggles == 0) break;

    SubdivisionFitReport fit;
    SubdivisionControlMesh refitted = fit_subdivision_surface(input, moved, options.fit, &fit);
    iterations += fit.iterations;
    ++rounds.rounds;
    rounds.rms.push_back(fit.rms);
    if (!(fit.rms < best_fit.rms)) break;
    const double gain = 1 - fit.rms / best_fit.rms;
    best = std::move(refitted);
    best_fit = std::move(fit);
    ++rounds.rounds_kept;
    if (gain < options.min_gain) break;
  }
  if (fit_report) {
    *fit_report = best_fit;
    fit_report->iterations = iterations;
  }
  if (report) *report = std::move(rounds);
  return best;
}

}  // namespace cadnurbs
