#include <cmath>
#include <filesystem>
#include <iostream>

#include "analysis/normals/crease_normals.hpp"
#include "analysis/normals/orient_faces.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/weld_vertices.hpp"
#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "converters/file_formats.hpp"
#include "converters/scene_preparation.hpp"
#include "formats/common/file_io.hpp"
#include "formats/stl/stl_reader.hpp"

namespace cadnurbs {

// The description tells what TOL and DEG do: no option needs a line of its own.
const CommandSpec& normals_command_spec() {
  static const CommandSpec spec = {
      "normals",
      "IN.stl -o OUT [--crease-angle DEG] [--weld TOL]",
      "Welds the triangles of IN (vertices closer than TOL become one; default 1e-6 of the bounding-box\n"
      "diagonal), drops collapsed and duplicate triangles, orients the faces consistently (closed parts\n"
      "outward) and gives every corner a normal: faces joined by an edge whose dihedral angle is below the\n"
      "crease angle (default 30 degrees) share one normal (angle-weighted), faces across a sharper edge do\n"
      "not (VRML's creaseAngle). OUT: .wrl .x3dv .x3d (an IndexedFaceSet with normal and normalIndex),\n"
      ".ply .obj (vertices split where normals differ).",
      {{"output", "OUT", ""}, {"crease-angle", "DEG", ""}, {"weld", "TOL", ""}},
      "",
  };
  return spec;
}

namespace {

constexpr double kDefaultCreaseDegrees = 30.0;

}  // namespace

int run_normals(const std::vector<std::string>& args, const CommandContext&) {
  const Arguments a = parse_arguments(normals_command_spec(), args);
  if (a.has("help")) {
    std::cout << command_help(normals_command_spec());
    return 0;
  }
  if (a.positional.size() != 1 || !a.has("output")) throw UsageError("needs one input and -o OUT (see --help)");
  const std::string in = a.positional[0], out = a.value("output");
  std::error_code ec;
  if (std::filesystem::equivalent(in, out, ec)) throw UsageError(out + ": output would overwrite the input");
  const double degrees = a.number("crease-angle", kDefaultCreaseDegrees);
  if (!(degrees >= 0 && degrees <= 180)) throw UsageError("--crease-angle must be 0 to 180 degrees");
  const double tolerance = a.number("weld", -1.0);
  if (a.has("weld") && !(tolerance >= 0 && std::isfinite(tolerance))) throw UsageError("--weld must be 0 or more");
  output_format(out);  // refuse an unknown output before the work

  // An STL file is read with equal corners merged and without its facet normals: the command makes its
  // own, and the soup's three copies of every corner would be the largest thing in memory.
  const bool stl = input_format(in).extensions.front() == ".stl";
  const Scene scene = stl ? Scene{} : read_scene(in);
  TriangleMesh triangles =
      stl ? read_stl(in, {.facet_normals = false, .merge_equal_points = true}) : scene_triangles(scene);
  if (triangles.triangles.empty()) throw FileError(in + ": no triangles to give normals to");
  checked_mesh_diagonal(triangles, in);
  const std::size_t corners = 3 * triangles.triangles.size();
  WeldReport weld;
  const double tol = a.has("weld") ? tolerance : default_weld_tolerance(triangles);
  // Each step takes the previous one's mesh over (no copies: on millions of triangles they would be most
  // of the memory), and the crease step the edge partners orient_faces found.
  TriangleMesh welded = weld_vertices(std::move(triangles), tol, &weld);
  if (welded.triangles.empty())
    throw FileError(in + ": every triangle collapses when welded at " + a.value("weld", std::to_string(tol)));
  OrientReport orient;
  SidePartners partners;
  TriangleMesh oriented = orient_faces(std::move(welded), &orient, nullptr, &partners);
  CreaseNormalsReport creases;
  const TriangleMesh shaded = with_crease_normals(std::move(oriented), degrees * M_PI / 180.0, &creases, &partners);

  Scene result;
  result.unit = scene.unit;
  result.source_unit = scene.source_unit;
  result.root.name = std::filesystem::path(in).stem().string();
  result.root.shapes.push_back({result.root.name, shaded, std::nullopt});
  SceneWriteOptions options;
  options.title = std::filesystem::path(in).filename().string();
  write_scene(out, result, options);
  std::cout << in << ": " << corners << " corners at " << weld.input_vertices
            << " distinct points, welded at " << tol << " " << scene.unit.name << " to " << weld.output_vertices
            << " vertices (largest move " << weld.largest_merge_distance << "), "
            << weld.collapsed_triangles << " collapsed and " << weld.zero_area_triangles
            << " zero-area triangles dropped\n"
            << in << ": " << orient.components << (orient.components == 1 ? " component (" : " components (")
            << orient.closed_components << " closed), " << orient.flipped_triangles << " triangles flipped, "
            << orient.duplicate_triangles << " duplicates dropped, " << orient.non_orientable_components
            << " non-orientable (" << orient.inconsistent_edges << " edges left inconsistent), "
            << orient.non_manifold_edges << " non-manifold and " << orient.boundary_edges << " boundary edges\n"
            << out << ": " << shaded.triangles.size() << " triangles, " << creases.distinct_normals
            << " distinct corner normals at a crease angle of " << degrees << " degrees (" << creases.smooth_edges
            << " smooth, " << creases.sharp_edges << " sharp edges)\n";
  return 0;
}

}  // namespace cadnurbs
