#include <filesystem>
#include <iostream>

#include "analysis/tessellate_uniform.hpp"
#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "converters/scene_io.hpp"
#include "core/bounding_box.hpp"

namespace cadnurbs {

namespace {
const char* kHelp =
    "usage: cadnurbs convert IN -o OUT [options]\n"
    "Reads IN (.stl, .wrl, .x3dv, .x3d) and writes OUT in the format its extension names\n"
    "(.wrl VRML97 with NURBS nodes, .x3dv X3D classic, .x3d X3D XML, .stl).\n"
    "  --mesh              write triangles: every NURBS surface tessellated uniformly\n"
    "  --steps N           steps per knot span for --mesh (default 8)\n"
    "  --precision N       write every number with N significant digits (default: the fewest\n"
    "                      digits that keep coordinates within 1e-6 of the model size)\n"
    "  --euclidean         write/read control points as Euclidean points with separate weights\n"
    "                      (default: homogeneous w*P, the convention of current viewers)\n"
    "  --self-contained    VRML97: paste the NURBS PROTO implementations into the file\n";
}  // namespace

int run_convert(const std::vector<std::string>& args) {
  const Arguments a =
      parse_arguments("convert", args, {"output", "steps", "precision"}, {"mesh", "euclidean", "self-contained", "help"});
  if (a.has("help")) {
    std::cout << kHelp;
    return 0;
  }
  if (a.positional.size() != 1 || !a.has("output")) throw UsageError("needs one input and -o OUT (see --help)");
  const std::string in = a.positional[0], out = a.value("output");
  std::error_code ec;
  if (std::filesystem::equivalent(in, out, ec)) throw UsageError(out + ": output would overwrite the input");
  const int steps = a.integer("steps", 8);
  if (steps < 1) throw UsageError("--steps must be at least 1");
  const int precision = a.integer("precision", 0);
  if (a.has("precision") && (precision < 1 || precision > 17)) throw UsageError("--precision must be 1 to 17");

  const bool homogeneous = !a.has("euclidean");
  const Scene scene = read_scene(in, homogeneous);
  SceneWriteOptions options;
  options.homogeneous_control_points = homogeneous;
  options.significant_digits = precision;
  options.self_contained = a.has("self-contained");
  options.title = std::filesystem::path(in).filename().string();
  // The mesh keeps the NURBS file's Viewpoint so that both render from the same place.
  options.viewpoint = framing_viewpoint(scene_bounding_box(scene));
  const bool mesh = a.has("mesh") || is_mesh_only_format(out);
  const Scene written = mesh ? tessellate_uniform(scene, steps) : scene;
  write_scene(out, written, options);
  const SceneCounts c = count_entities(written);
  std::cout << out << ": " << c.surfaces << " NURBS surfaces, " << c.meshes << " meshes (" << c.mesh_triangles
            << " triangles)\n";
  return 0;
}

}  // namespace cadnurbs
