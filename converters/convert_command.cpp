#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "analysis/tessellate_uniform.hpp"
#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "converters/file_formats.hpp"
#include "converters/scene_preparation.hpp"
#include "core/bounding_box.hpp"
#include "core/length_unit.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

std::string help() {
  return "usage: cadnurbs convert IN -o OUT [options]\n"
         "Reads IN (" + extension_list(true) + ")\n"
         "and writes OUT in the format its extension names (" + extension_list(false) + ").\n"
         "VRML/X3D NURBS output is compact and exact by default: repeated geometry and appearances\n"
         "written once (DEF/USE), straight trimming runs as polylines, planar faces bounded by straight\n"
         "edges as exact polygons, knots as small numbers where an affine map allows; nothing moves by\n"
         "more than the written precision. gzip'd forms: .wrz .wrl.gz .x3dvz .x3dz (read too).\n"
         "  --from EXT          read IN as the format of extension EXT (step, stl, ...) whatever its name\n"
         "  --mesh              write triangles: every NURBS surface tessellated so that no point of\n"
         "                      the mesh is farther than the deviation from the exact surface\n"
         "                      (formats that hold triangles only imply it)\n"
         "  --deviation D       that maximum deviation, in the output unit (default: 0.001 x the\n"
         "                      bounding-box diagonal)\n"
         "  --check-areas       --mesh: also compare every face's mesh area with its exact area and\n"
         "                      count the faces that differ by more than a mesh within D may (a fold)\n"
         "  --display-deviation D  NURBS output: uTessellation / vTessellation / trimming-curve counts\n"
         "                      with which viewers that tessellate uniformly (X_ITE, view3dscene) draw\n"
         "                      every face within D (default: as --deviation; 0: none written)\n"
         "  --steps N           instead: uniform tessellation, N steps per knot span (seed 000's method)\n"
         "  --simplify D        NURBS output: remove the knots that faces and 3D curves do not need within\n"
         "                      D/8 (knot removal; trims kept, so shared edges part by at most D/4, what\n"
         "                      sewing bridges at D); then the deviation is measured (the original faces\n"
         "                      meshed within D/4 against the simplified ones) and the meshes at D compared\n"
         "                      for open edges (an edge opened: redone within D/64, then D/512, else none\n"
         "                      removed); fails when the deviation exceeds D\n"
         "  --exact-nurbs       every face as the trimmed NURBS of its source, orders, knots, weights and\n"
         "                      control points unchanged (only DEF/USE sharing applies)\n"
         "  --units U           output lengths in U: mm (default), cm, m, in, kicad (0.1 inch, the unit\n"
         "                      KiCad's VRML reader assumes); the file records the unit\n"
         "  --precision N       write every number with N significant digits (default: the fewest\n"
         "                      digits that keep coordinates within 1e-6 of the model size)\n"
         "  --pretty            VRML/X3D: indented, one field per line\n"
         "  --euclidean         write/read control points as Euclidean points with separate weights\n"
         "                      (default: homogeneous w*P, the convention of current viewers)\n"
         "  --self-contained    VRML97: paste the NURBS PROTO implementations into the file\n"
         "  .cnb (cadnurbs compact binary NURBS, docs/cnb.md): --deviation D is its bound (default 0.001 x\n"
         "                      the diagonal): control points and trims quantised so that no decoded point\n"
         "                      moves by more than D\n"
         "  --compress C        .glb: draco (default), meshopt or none. .glb and .drc quantise positions: the\n"
         "                      mesh is made within 0.7 D and the coarsest grid that moves no vertex by more\n"
         "                      than 0.3 D is taken, so the decoded mesh stays within D (metres, +Y up in .glb)\n"
         "A STEP/IGES face that cannot be written as a trimmed NURBS is written as a mesh instead;\n"
         "convert lists each such face and says how many there were.\n" +
         kReadLimitHelp;
}

// The share of D a quantising format's mesh is tessellated to (the rest is the quantisation's).
constexpr double kTessellationShare = 0.7;

void print_compaction(const std::string& out, const CompactReport& r) {
  std::cout << out << ": compact: " << r.planar_faces << " planar faces as exact polygons in " << r.polygon_meshes
            << " face sets, " << r.untrimmed << " trims that were the domain boundary dropped, " << r.straight_runs
            << " straight trimming runs as polylines, " << r.reparametrised << " knot vectors as small numbers, " << r.knots_removed
            << " trimming-curve knots removed, "
            << r.instanced << " repeated parts placed as copies\n";
}

// "STL" for "part.stl".
std::string upper_extension(const std::string& path) {
  std::string name = file_extension(path).substr(1);
  for (auto& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

// Takes the NURBS curves out of `node` and its children (a format that holds triangles only has no place
// for them); returns how many.
int drop_curves(SceneNode& node) {
  const auto before = node.shapes.size();
  std::erase_if(node.shapes, [](const Shape& shape) { return std::holds_alternative<NurbsCurve>(shape.geometry); });
  int dropped = static_cast<int>(before - node.shapes.size());
  for (auto& child : node.children) dropped += drop_curves(child);
  return dropped;
}

// --simplify D: the simplified scene, its one-line summary printed; throws FileError naming `in` when the
// certified deviation exceeds D. (An opened edge never gets here: simplified_scene then keeps the input.)
Scene simplify_certified(const std::string& in, const std::string& out, const Scene& scene, double d, int precision) {
  SimplifiedScene s = simplified_scene(scene, d, written_tolerance(scene, precision));
  const auto number = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return std::string(text);
  };
  const std::string unit = " " + scene.unit.name;
  const auto open = [&](const EdgeCounts& e) {
    return std::to_string(e.boundary) + " open edges (" + number(e.boundary_length) + unit + ")";
  };
  std::cout << out << ": simplified within " << number(d) << unit << " (faces moved by at most " << number(s.max_move)
            << ", " << s.attempts << (s.attempts == 1 ? " attempt" : " attempts") << "; " << s.instanced
            << " repeated parts placed as copies first): " << s.knots.knots_removed << " knots removed ("
            << s.knots.surfaces_changed << " surfaces, " << s.knots.curves_changed << " curves), control points "
            << s.knots.control_points_before << " -> " << s.knots.control_points_after << ", certified deviation "
            << number(s.certified_deviation) << unit << " (measured " << number(s.measured) << " + mesh "
            << number(s.mesh_deviation) << " + copies " << number(s.copies_moved) << "; curves " << number(s.knots.curve_deviation) << "), meshed at "
            << number(d) << ": " << open(s.open_before) << " before, " << open(s.open_after) << " after, "
            << s.unshared_after << " unshared edge uses\n";
  if (s.certified_deviation > d)
    throw FileError(in + ": --simplify " + number(d) + ": the certified deviation " + number(s.certified_deviation) +
                    " exceeds it");
  return std::move(s.scene);
}

}  // namespace

int run_convert(const std::vector<std::string>& args) {
  const Arguments a = parse_arguments("convert", args, {"output", "steps", "precision", "deviation", "display-deviation", "units", "compress",
                                       "time-limit", "memory-limit", "from", "simplify"},
                                      {"mesh", "euclidean", "self-contained", "exact-nurbs", "pretty", "check-areas", "help"});
  if (a.has("help")) {
    std::cout << help();
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
  const double display_deviation = a.number("display-deviation", -1.0);
  if (a.has("display-deviation") && !(display_deviation >= 0)) throw UsageError("--display-deviation must be 0 or more");
  const double simplify = a.number("simplify", 0.0);
  if (a.has("simplify") && !(simplify > 0 && std::isfinite(simplify))) throw UsageError("--simplify must be positive");
  const int precision = a.integer("precision", 0);
  if (a.has("precision") && (precision < 1 || precision > 17)) throw UsageError("--precision must be 1 to 17");
  std::optional<LengthUnit> unit;
  if (a.has("units")) {
    unit = length_unit_named(a.value("units"));
    if (!unit) throw UsageError("--units: unknown unit '" + a.value("units") + "' (mm, cm, m, in, kicad)");
  }
  const FileFormat& format = output_format(out);  // refuse an unknown output before the work
  const FileFormat& in_format = a.has("from") ? named_input_format(a.value("from")) : input_format(in);

  const bool homogeneous = !a.has("euclidean");
  apply_read_limits(a);
  const BrepTranslation loaded = load_scene_as(in, in_format, homogeneous);
  for (const auto& line : loaded.repairs) std::cerr << in << ": " << line << "\n";
  for (const auto& f : loaded.fallbacks)
    std::cerr << in << ": " << f.node << " face " << f.face_index << " (" << f.surface_type
              << ") written as a mesh: " << f.reason << "\n";
  const Scene scene = unit ? in_unit(loaded.scene, *unit) : loaded.scene;

  SceneWriteOptions options;
  options.homogeneous_control_points = homogeneous;
  options.significant_digits = precision;
  options.self_contained = a.has("self-contained");
  options.pretty = a.has("pretty");
  options.title = std::filesystem::path(in).filename().string();
  if (a.has("compress")) {
    if (file_extension(out) != ".glb") throw UsageError("--compress applies to .glb output only");
    options.compression = a.value("compress");
  }
  const auto box = scene_bounding_box(scene);
  const double diagonal = checked_diagonal(scene, in);
  // The mesh keeps the NURBS file's Viewpoint so that both render from the same place.
  options.viewpoint = framing_viewpoint(box);
  options.display_deviation = display_deviation >= 0 ? display_deviation : 1e-3 * diagonal;
  // --deviation asks for a mesh, except for a NURBS format that quantises (.cnb): there it is its bound.
  const bool nurbs_within_deviation = format.quantises && !format.meshes_only;
  const bool mesh = a.has("mesh") || a.has("steps") || (a.has("deviation") && !nurbs_within_deviation) ||
                    format.meshes_only;
  if (a.has("simplify") && mesh) throw UsageError("--simplify applies to NURBS output only");
  const Scene simpler = a.has("simplify") ? simplify_certified(in, out, scene, simplify, precision) : Scene{};
  const Scene& source = a.has("simplify") ? simpler : scene;
  if (nurbs_within_deviation) options.quantisation_budget = deviation > 0 ? deviation : default_deviation(diagonal, in);
  Scene written;
  std::string how;
  if (mesh && steps > 0) {
    written = tessellate_uniform(scene, steps);
    how = ", uniform " + std::to_string(steps) + " steps per span";
  } else if (mesh) {
    const double d = deviation > 0 ? deviation : default_deviation(diagonal, in);
    const bool check_areas = a.has("check-areas");
    // A quantising writer gets its share of D: the mesh at 0.7 D, vertices moved by at most 0.3 D.
    const double tessellated = format.quantises ? kTessellationShare * d : d;
    if (format.quantises) options.quantisation_budget = d - tessellated;
    CertifiedMesh meshed = certified_mesh(loaded, scene, tessellated, check_areas);
    if (meshed.sewn) {
      const SewingReport& sewing = meshed.sewing;
      std::cout << in << ": sewn at " << meshed.sewing_tolerance.first << " " << scene.unit.name << " (gaps up to "
                << meshed.sewing_tolerance.largest << "; widest bridged " << sewing.widest_gap << "): " << sewing.shared_edges
                << " shared edges, " << sewing.open_pieces << " open boundary pieces, " << sewing.cuts
                << " pieces cut at a neighbour's vertex, " << sewing.polygon_faces << " polygons as faces\n";
    }
    const TessellationReport& report = meshed.report;
    written = std::move(meshed.meshes);
    how = ", max deviation " + std::to_string(d) + " " + scene.unit.name +
          (format.quantises ? " (mesh within " + std::to_string(tessellated) + ", positions quantised within " +
                                  std::to_string(options.quantisation_budget) + ")"
                            : std::string()) +
          "; certified " +
          std::to_string(report.certified_deviation) + ", " + std::to_string(report.uncertified_triangles) +
          " uncertified triangles, " + std::to_string(report.unshared_edge_uses) + " unshared edge uses" +
          (check_areas ? ", " + std::to_string(report.faces_beyond_area_allowance) + " faces beyond their area allowance"
                       : std::string());
  } else if (format.compact && !a.has("exact-nurbs")) {
    CompactReport report;
    written = compact_scene(source, written_tolerance(scene, precision), &report);
    print_compaction(out, report);
  } else {
    written = source;
  }
  if (format.meshes_only) {
    const int curves = drop_curves(written.root);
    if (curves > 0)
      std::cerr << in << ": " << curves << " NURBS curve" << (curves == 1 ? "" : "s") << " left out: "
                << upper_extension(out) << " holds triangles only\n";
  }
  write_scene(out, written, options);
  const SceneCounts c = count_entities(written);
  std::cout << out << ": " << c.surfaces << " NURBS surfaces, " << c.polygon_meshes << " polygon sets ("
            << c.polygons << " polygons), " << c.meshes << " meshes (" << c.mesh_triangles << " triangles" << how
            << ")\n";
  if (loaded.face_count > 0)
    std::cout << in << ": " << loaded.face_count << " faces: " << loaded.face_count - int(loaded.fallbacks.size())
              << " as trimmed NURBS, " << loaded.fallbacks.size() << " fell back to a mesh\n";
  return 0;
}

}  // namespace cadnurbs
