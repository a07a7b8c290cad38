#pragma once
// The whole Loop fit of a triangle mesh, as `fit-loop` and `report` run it: weld, decimate with
// features kept, fit, and measure the limit surface against the input next to a plain quadric
// decimation with as many vertices (the thing a user would otherwise publish).
#include <optional>
#include <string>

#include "analysis/subdivision_fit/fit_to_tolerance.hpp"
#include "analysis/subdivision_fit/fit_best_start.hpp"
#include "analysis/subdivision_fit/fit_connectivity_rounds.hpp"
#include "analysis/subdivision_fit/refit_watching_spans.hpp"
#include "analysis/measure/measure_deviation.hpp"

namespace cadnurbs {

struct SubdivisionFitRequest {
  int control_vertices = 200;       // the decimation's target (the first round's, with a tolerance)
  double tolerance = 0;             // > 0: keep more input vertices until the fit is within it
  double crease_angle_degrees = 30; // input edges at or above it are creases (normals' default too; 40 left the
                                    // OCC bottle's shoulder smooth: RMS 0.68 of QEM's against 0.47, pooled by count)
  int levels = 3;                   // refinements of the limit mesh
  // Without a tolerance: after the fit, rounds of one sweep of edge swaps and tag toggles where they
  // lower the local error, each followed by the fit again (fit_connectivity_rounds). Off by
  // default: with two sweeps then one fit (stop 31) it took the corpus's tray from 0.77 to 0.26 of the
  // quadric decimation's RMS (bottle_ascii 0.52 to 0.35), but cost some 10 to 20 plain fits.
  bool improve_connectivity = false;
  int connectivity_rounds = 4;      // at most; fewer once a round's fit gains under 1 %
  // Vertices closer than this are one (< 0: 1e-4 of the bounding-box diagonal, 100 times the normals'
  // default: a fit needs connectivity, and ASCII exporters round shared corners differently, by
  // up to 6e-5 of the diagonal in the corpus's OCC bottle).
  double weld_tolerance = -1;
  const SubdivisionControlMesh* saved_control = nullptr;  // given: no fit, only its limit surface measured
  std::string source = "the mesh";                 // the input file, for messages
};

struct SubdivisionFitMeasure {
  int input_vertices = 0, input_triangles = 0;  // after welding
  SubdivisionControlMesh control;
  TriangleMesh limit;                 // `levels` refinements, vertices at their limit points
  FitStartsReport starts;            // the decimation and the fits from the three starts (with a tolerance: the
                                      // last round's decimation and fit, one start only)
  SubdivisionFitReport fit;                  // the fit kept last (its iterations: all fits')
  ConnectivityRoundsReport connectivity;  // the moves tried and kept, the rounds' fits (no candidates: not run)
  // Fitted from the starts (no tolerance, no saved control mesh): the last refit with every limit
  // point fitted (refit_watching_spans), the result when kept.
  std::optional<SpanRefitReport> span_refit;
  int rounds = 1;                     // decimate-and-fit rounds (more with a tolerance)
  bool tolerance_met = false;         // with a tolerance: the fit is within it at its own samples
  DeviationStats limit_distance;      // two-sided, limit mesh to input (mesh_distance)
  TriangleMesh qem;                   // plain quadric decimation to the control mesh's vertex count
  DeviationStats qem_distance;
  // Storage as the thesis counts it: floats, integers (triangle corners), tag integers.
  long control_floats = 0, control_integers = 0, control_tags = 0;
  long input_floats = 0, input_integers = 0;  // the welded input mesh

  // A connectivity round's fit beat the fit before the moves; the last such is the result.
  bool connectivity_kept() const { return connectivity.rounds_kept > 0; }
};

// Takes the triangles of an STL (or any mesh; unwelded is fine) and the request; returns the fit
// and its measures. Refuses (std::invalid_argument) a mesh without triangles.
SubdivisionFitMeasure measure_subdivision_fit(const TriangleMesh& triangles, const SubdivisionFitRequest& request);

}  // namespace cadnurbs
