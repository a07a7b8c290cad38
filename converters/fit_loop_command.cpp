#include <filesystem>
#include <iostream>

#include "analysis/mesh/scene_triangles.hpp"
#include "core/number_format.hpp"
#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "converters/file_formats.hpp"
#include "converters/scene_preparation.hpp"
#include "converters/subdivision_fit_measurement.hpp"
#include "formats/common/file_io.hpp"
#include "formats/obj/control_mesh_obj.hpp"

namespace cadnurbs {

const CommandSpec& fit_loop_command_spec() {
  static const CommandSpec spec = {
      "fit-loop",
      "IN.stl -o CONTROL.obj [--surface LIMIT] [--control-vertices N] [--tolerance D] [--crease-angle DEG] "
      "[--levels K] [--weld TOL] [--connectivity]\n"
      "CONTROL.obj --input IN.stl [--surface LIMIT] [--levels K] [--weld TOL]",
      "Fits a Loop subdivision surface to the triangles of IN: a control mesh by quadric decimation to N\n"
      "vertices (default 200) with the edges sharper than the crease angle (default 30 degrees) kept and\n"
      "tagged as creases, then control points solved by least squares so that the limit surface fits\n"
      "IN both ways. Two more starts are fitted at as many vertices, with both sides weighted by area: a\n"
      "plain quadric decimation tagged where it is sharp itself, and one under the smallest guard on the\n"
      "removed vertices' distance that reaches the count; the fit kept is the one whose limit\n"
      "surface's RMS and max to IN, each as a share of the plain decimation's, sum lowest.\n"
      "A last fit then also fits the limit points whose nearest point of IN faces away (a surface that\n"
      "spans a gap); it is kept when its limit surface scores lower (not with a tolerance).\n"
      "Prints the RMS and maximum two-sided distance to IN, next to a plain quadric decimation with as\n"
      "many vertices, and storage. Given a saved CONTROL.obj, it measures that control mesh's limit\n"
      "surface against --input.",
      {
          {"output", "CONTROL.obj", "the control mesh with its tags (OBJ; docs/control_mesh_obj.md)"},
          {"surface", "LIMIT",
           "the limit surface (K refinements, vertices at their limit points), as a\n"
           "mesh: .stl .obj .wrl .x3dv .ply ..."},
          {"control-vertices", "N", "the control mesh's vertex count N (default 200)"},
          {"tolerance", "D",
           "(first start only) keeps more of IN's vertices where the surface stays\n"
           "farther than D, decimates and fits again, until it is within D (N is the\n"
           "first round's count)"},
          {"crease-angle", "DEG", "IN's edges sharper than DEG are creases (default 30 degrees)"},
          {"levels", "K", "refinements of the limit surface, 1 to 5 (default 3)"},
          {"weld", "TOL",
           "IN's vertices closer than TOL are welded first (default 1e-4 of the\n"
           "bounding-box diagonal)"},
          {"connectivity", "",
           "then tries edge swaps and crease and corner tag toggles, keeps those after\n"
           "which a local re-fit gets closer, and fits again; up to 4 such rounds, while\n"
           "each fit gains 1 % or more (much slower; not with a tolerance)"},
          {"input", "IN.stl", "with a saved CONTROL.obj: the mesh its limit surface is measured against"},
      },
      "",
  };
  return spec;
}

int run_fit_loop(const std::vector<std::string>& args, const CommandContext&) {
  const Arguments a = parse_arguments(fit_loop_command_spec(), args);
  if (a.has("help")) {
    std::cout << command_help(fit_loop_command_spec());
    return 0;
  }
  if (a.positional.size() != 1) throw UsageError("needs one input (see --help)");
  const std::string in = a.positional[0];
  const bool from_saved = std::filesystem::path(in).extension() == ".obj";
  if (!from_saved && !a.has("output")) throw UsageError("needs -o CONTROL.obj (see --help)");
  if (from_saved && !a.has("input")) throw UsageError("a saved control mesh needs --input IN.stl to measure against");
  SubdivisionFitRequest request;
  request.control_vertices = a.integer("control-vertices", request.control_vertices);
  if (request.control_vertices < 4) throw UsageError("--control-vertices must be 4 or more");
  request.tolerance = a.number("tolerance", 0);
  if (a.has("tolerance") && !(request.tolerance > 0 && std::isfinite(request.tolerance)))
    throw UsageError("--tolerance must be a positive number");
  request.crease_angle_degrees = a.number("crease-angle", request.crease_angle_degrees);
  if (!(request.crease_angle_degrees >= 0 && request.crease_angle_degrees <= 180))
    throw UsageError("--crease-angle must be 0 to 180 degrees");
  request.weld_tolerance = a.number("weld", -1.0);
  if (a.has("weld") && !(request.weld_tolerance >= 0 && std::isfinite(request.weld_tolerance)))
    throw UsageError("--weld must be 0 or more");
  request.improve_connectivity = a.has("connectivity");
  if (request.improve_connectivity && (a.has("tolerance") || from_saved))
    throw UsageError("--connectivity goes neither with --tolerance nor with a saved control mesh");
  request.levels = a.integer("levels", request.levels);
  if (request.levels < 1 || request.levels > 5) throw UsageError("--levels must be 1 to 5");
  for (const std::string option : {"output", "surface"}) {
    if (!a.has(option)) continue;
    std::error_code ec;
    for (const std::string& source : {in, a.value("input")})
      if (!source.empty() && std::filesystem::equivalent(source, a.value(option), ec))
        throw UsageError(a.value(option) + ": output would overwrite an input");
  }
  if (a.has("output") && std::filesystem::path(a.value("output")).extension() != ".obj")
    throw UsageError(a.value("output") + ": the control mesh is written as .obj");
  if (a.has("surface")) output_format(a.value("surface"));  // refuse an unknown format before the work

  const std::string mesh_path = from_saved ? a.value("input") : in;
  const Scene scene = read_scene(mesh_path);
  const TriangleMesh triangles = scene_triangles(scene);
  if (triangles.triangles.empty()) throw FileError(mesh_path + ": no triangles to fit");
  checked_mesh_diagonal(triangles, mesh_path);
  request.source = mesh_path;
  SubdivisionControlMesh saved;
  if (from_saved) {
    saved = read_control_mesh_obj(in);
    request.saved_control = &saved;
  }
  const SubdivisionFitMeasure m = measure_subdivision_fit(triangles, request);

  if (a.has("output")) write_control_mesh_obj(a.value("output"), m.control);
  if (a.has("surface")) {
    Scene limit;
    limit.unit = scene.unit;
    limit.source_unit = scene.source_unit;
    limit.root.name = std::filesystem::path(in).stem().string() + "-limit";
    limit.root.shapes.push_back({limit.root.name, m.limit, std::nullopt});
    SceneWriteOptions options;
    options.title = limit.root.name;
    write_scene(a.value("surface"), limit, options);
  }
  const std::string unit = scene.unit.name;
  std::cout << mesh_path << ": " << m.input_triangles << " triangles, " << m.input_vertices << " welded vertices\n";
  if (!from_saved) {
    const DecimationReport& d = m.starts.decimation;
    std::cout << "control mesh: " << m.control.positions.size() << " vertices, " << m.control.triangles.size()
              << " triangles, " << m.control.crease_edges.size() << " crease edges, " << m.control.corner_vertices.size()
              << " tagged corners (" << d.sharp_input_edges << " sharp input edges, " << d.locked_corners
              << " corners locked, " << d.skipped_triangles << " non-manifold triangles left out of the decimation); "
              << m.fit.iterations << " solves"
              << (request.tolerance > 0 ? ", " + std::to_string(m.rounds) + " rounds: " +
                                              (m.tolerance_met ? "within " : "NOT within ") + a.value("tolerance") +
                                              " at the fit's samples"
                                        : std::string())
              << "\n";
    if (request.tolerance <= 0) {
      const FitStartsReport& st = m.starts;
      auto figures = [&](const StartFit& f) {
        return message_number(f.distance.rms) + " / " + message_number(f.distance.max) + " " + unit;
      };
      const char* kept = st.kept == FitStart::guarded ? "guarded" : st.kept == FitStart::plain ? "plain" : "features";
      std::cout << "start kept: " << kept << " (limit surface to input, two-sided RMS / max, from the start that keeps the "
                << "input's sharp edges " << figures(st.features) << "; fitted with both sides weighted by area, "
                << "from the plain quadric decimation " << figures(st.plain) << "; from the quadric decimation "
                << (st.guard > 0 ? "that leaves no input vertex farther than " + message_number(st.guard) + " " + unit
                                 : std::string("(no distance guard reached the count)"))
                << ", " << figures(st.guarded) << ")\n";
    }
  }
  if (m.connectivity.moves.candidates > 0) {
    const ConnectivityRoundsReport& c = m.connectivity;
    std::cout << "connectivity: " << c.moves.candidates << " local re-fits, " << c.moves.swaps << " swaps, "
              << c.moves.corner_toggles << " corner and " << c.moves.crease_toggles << " crease tag toggles kept; "
              << c.rounds << " rounds fitted (RMS at the fit's samples:";
    for (double rms : c.rms) std::cout << " " << rms;
    std::cout << " " << unit << "); "
              << (m.connectivity_kept() ? "round " + std::to_string(c.rounds_kept) + "'s fit kept"
                                      : std::string("no round's fit was closer, the first fit kept"))
              << "\n";
  }
  if (m.span_refit) {
    const DeviationStats& d = m.span_refit->refit.distance;
    std::cout << "last refit with every limit point fitted, those facing away too: two-sided RMS / max "
              << message_number(d.rms) << " / " << message_number(d.max) << " " << unit << "; "
              << (m.span_refit->kept ? "kept" : "not kept, the fit before it was closer") << "\n";
  }
  std::cout << "limit surface (" << request.levels << " levels, " << m.limit.triangles.size()
            << " triangles) to input, two-sided: RMS " << m.limit_distance.rms << " " << unit << ", max "
            << m.limit_distance.max << " " << unit << "\n"
            << "quadric decimation to " << m.control.positions.size() << " vertices, two-sided: RMS "
            << m.qem_distance.rms << " " << unit << ", max " << m.qem_distance.max << " " << unit << " (RMS ratio "
            << m.limit_distance.rms / m.qem_distance.rms << ", max ratio " << m.limit_distance.max / m.qem_distance.max
            << ")\n"
            << "storage: control mesh " << m.control_floats << " floats, " << m.control_integers << " integers, "
            << m.control_tags << " tag integers; input " << m.input_floats << " floats, " << m.input_integers
            << " integers\n";
  return 0;
}

}  // namespace cadnurbs
