#include <filesystem>
#include <iostream>

#include "analysis/tessellate_to_deviation.hpp"
#include "analysis/tessellate_uniform.hpp"
#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "converters/scene_io.hpp"
#include "core/bounding_box.hpp"

namespace cadnurbs {

namespace {
const char* kHelp =
    "usage: cadnurbs convert IN -o OUT [options]\n"
    "Reads IN (.step .stp .iges .igs .stl .wrl .x3dv .x3d) and writes OUT in the format its\n"
    "extension names (.wrl VRML97 with NURBS nodes, .x3dv X3D classic, .x3d X3D XML, .step, .iges;\n"
    "meshes: .stl .ply, or IndexedFaceSet in .wrl .x3dv .x3d with --mesh).\n"
    "  --mesh              write triangles: every NURBS surface tessellated so that no point of\n"
    "                      the mesh is farther than the deviation from the exact surface\n"
    "  --deviation D       that maximum deviation in mm (default: 0.001 x the bounding-box diagonal)\n"
    "  --steps N           instead: uniform tessellation, N steps per knot span (seed 000's method)\n"
    "  --precision N       write every number with N significant digits (default: the fewest\n"
    "                      digits that keep coordinates within 1e-6 of the model size)\n"
    "  --euclidean         write/read control points as Euclidean points with separate weights\n"
    "                      (default: homogeneous w*P, the convention of current viewers)\n"
    "  --self-contained    VRML97: paste the NURBS PROTO implementations into the file\n"
    "A STEP/IGES face that cannot be written as a trimmed NURBS is written as a mesh instead;\n"
    "convert lists each such face and says how many there were.\n";
}  // namespace

int run_convert(const std::vector<std::string>& args) {
  const Arguments a = parse_arguments("convert", args, {"output", "steps", "precision", "deviation"},
                                      {"mesh", "euclidean", "self-contained", "help"});
  if (a.has("help")) {
    std::cout << kHelp;
    return 0;
  }
  if (a.positional.size() != 1 || !a.has("output")) throw UsageError("needs one input and -o OUT (see --help)");
  const std::string in = a.positional[0], out = a.value("output");
  std::error_code ec;
  if (std::filesystem::equivalent(in, out, ec)) throw UsageError(out + ": output would overwrite the input");
  const int steps = a.integer("steps", 0);
  if (a.has("steps") && steps < 1) throw UsageError("--steps must be at least 1");
  const double deviation = a.number("deviation", 0.0);
  if (a.has("deviation") && !(deviation > 0)) throw UsageError("--deviation must be positive");
  if (a.has("deviation") && a.has("steps")) throw UsageError("--deviation and --steps exclude each other");
  const int precision = a.integer("precision", 0);
  if (a.has("precision") && (precision < 1 || precision > 17)) throw UsageError("--precision must be 1 to 17");

  const bool homogeneous = !a.has("euclidean");
  const LoadedScene loaded = load_scene(in, homogeneous);
  const Scene& scene = loaded.scene;
  for (const auto& f : loaded.fallbacks)
    std::cerr << in << ": " << f.node << " face " << f.face_index << " (" << f.surface_type
              << ") written as a mesh: " << f.reason << "\n";

  SceneWriteOptions options;
  options.homogeneous_control_points = homogeneous;
  options.significant_digits = precision;
  options.self_contained = a.has("self-contained");
  options.title = std::filesystem::path(in).filename().string();
  const auto box = scene_bounding_box(scene);
  // The mesh keeps the NURBS file's Viewpoint so that both render from the same place.
  options.viewpoint = framing_viewpoint(box);
  const bool mesh = a.has("mesh") || a.has("steps") || a.has("deviation") || is_mesh_only_format(out);
  Scene written = scene;
  std::string how;
  if (mesh && steps > 0) {
    written = tessellate_uniform(scene, steps);
    how = ", uniform " + std::to_string(steps) + " steps per span";
  } else if (mesh) {
    const double d = deviation > 0 ? deviation : 1e-3 * box.diagonal().norm();
    TessellationReport report;
    written = tessellate_to_deviation(scene, d, &report);
    how = ", max deviation " + std::to_string(d) + " mm";
  }
  write_scene(out, written, options);
  const SceneCounts c = count_entities(written);
  std::cout << out << ": " << c.surfaces << " NURBS surfaces, " << c.meshes << " meshes (" << c.mesh_triangles
            << " triangles" << how << ")\n";
  if (loaded.face_count > 0)
    std::cout << in << ": " << loaded.face_count << " faces: " << loaded.face_count - int(loaded.fallbacks.size())
              << " as trimmed NURBS, " << loaded.fallbacks.size() << " fell back to a mesh\n";
  return 0;
}

}  // namespace cadnurbs
