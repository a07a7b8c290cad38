#include "converters/subdivision_fit_measurement.hpp"

#include <stdexcept>

#include "analysis/measure/mesh_distance.hpp"
#include "analysis/subdivision/limit_surface.hpp"
#include "analysis/mesh/weld_vertices.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

TriangleMesh as_triangle_mesh(const SubdivisionControlMesh& control) { return {control.positions, control.triangles, {}}; }

}  // namespace

SubdivisionFitMeasure measure_subdivision_fit(const TriangleMesh& triangles, const SubdivisionFitRequest& request) {
  if (triangles.triangles.empty()) throw std::invalid_argument("measure_subdivision_fit: the mesh has no triangles");
  SubdivisionFitMeasure m;
  const double weld = request.weld_tolerance >= 0 ? request.weld_tolerance : 100 * default_weld_tolerance(triangles);
  const TriangleMesh input = weld_vertices(triangles, weld);
  if (input.triangles.empty()) throw FileError(request.source + ": every triangle collapses when welded at " + std::to_string(weld));
  m.input_vertices = static_cast<int>(input.positions.size());
  m.input_triangles = static_cast<int>(input.triangles.size());

  SubdivisionFitOptions options;
  options.levels = request.levels;
  if (request.saved_control) {
    m.control = *request.saved_control;
  } else {
    const double sharp_angle = request.crease_angle_degrees * M_PI / 180.0;
    if (request.tolerance > 0) {
      ToleranceFitReport rounds;
      m.control = fit_to_tolerance(input, request.control_vertices, sharp_angle, request.tolerance, options, &rounds);
      m.starts.decimation = rounds.decimation;
      m.starts.features.fit = m.fit = rounds.fit;
      m.rounds = rounds.rounds;
      m.tolerance_met = rounds.met;
    } else {
      m.control = fit_best_start(input, request.control_vertices, sharp_angle, options, &m.starts);
      m.fit = kept_start(m.starts).fit;
      m.fit.iterations = m.starts.features.fit.iterations + m.starts.plain.fit.iterations + m.starts.guarded.fit.iterations;
      // Every later fit weights as the kept start's did, so their RMS compare alike.
      options.balance_sides = start_balances_sides(m.starts.kept);
      if (request.improve_connectivity) {
        ConnectivityRoundsOptions rounds;
        rounds.moves.levels = request.levels;
        rounds.moves.sweeps = 1;
        rounds.fit = options;
        rounds.max_rounds = request.connectivity_rounds;
        SubdivisionFitReport refit;
        m.control = fit_connectivity_rounds(input, m.control, m.fit, rounds, &refit, &m.connectivity);
        refit.iterations += m.fit.iterations;
        if (m.connectivity_kept())
          m.fit = refit;
        else
          m.fit.iterations = refit.iterations;
      }
    }
  }
  m.limit = evaluate_limit_mesh(subdivision_limit_mesh(control_mesh_topology(m.control), request.levels), m.control.positions);
  // The starts measured the kept fit already, unless a tolerance, a saved control mesh or kept
  // connectivity moves took its place.
  const bool from_starts = !request.saved_control && request.tolerance <= 0;
  const bool measured = from_starts && !m.connectivity_kept();
  m.limit_distance = measured ? kept_start(m.starts).distance : mesh_distance(m.limit, input).overall;

  // The starts made this decimation already (same count, nothing kept) unless a tolerance or a
  // saved control mesh took their place.
  const int count = static_cast<int>(m.control.positions.size());
  if (static_cast<int>(m.starts.plain_decimation.positions.size()) == count) {
    m.qem = m.starts.plain_decimation;
    m.qem_distance = m.starts.plain_decimation_distance;
  } else {
    m.qem = as_triangle_mesh(decimate_control_mesh(input, count, -1));
    m.qem_distance = mesh_distance(m.qem, input).overall;
  }

  if (from_starts) {
    SpanRefitReport span;
    m.control = refit_watching_spans(input, m.control, m.limit_distance, m.qem_distance, options, &span);
    const int iterations = m.fit.iterations + span.refit.fit.iterations;
    if (span.kept) {
      m.fit = span.refit.fit;
      m.limit = evaluate_limit_mesh(subdivision_limit_mesh(control_mesh_topology(m.control), request.levels), m.control.positions);
      m.limit_distance = span.refit.distance;
    }
    m.fit.iterations = iterations;
    m.span_refit = span;
  }

  m.control_floats = 3L * static_cast<long>(m.control.positions.size());
  m.control_integers = 3L * static_cast<long>(m.control.triangles.size());
  m.control_tags = 2L * static_cast<long>(m.control.crease_edges.size()) + static_cast<long>(m.control.corner_vertices.size());
  m.input_floats = 3L * m.input_vertices;
  m.input_integers = 3L * m.input_triangles;
  return m;
}

}  // namespace cadnurbs
