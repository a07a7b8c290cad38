#include <cmath>
#include <filesystem>
#include <iostream>

#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "converters/file_formats.hpp"
#include "converters/conversion.hpp"
#include "converters/scene_preparation.hpp"
#include "core/length_unit.hpp"
#include "core/number_format.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

const CommandSpec& convert_command_spec() {
  static const CommandSpec spec = {
      "convert",
      "IN -o OUT [options]",
      "Reads IN (" + extension_list(true) + ")\n"
      "and writes OUT in the format its extension names (" + extension_list(false) + ").\n"
      "VRML/X3D NURBS output is compact and exact by default: repeated geometry and appearances\n"
      "written once (DEF/USE), straight trimming runs as polylines, planar faces bounded by straight\n"
      "edges as exact polygons, knots as small numbers where an affine map allows; nothing moves by\n"
      "more than the written precision. gzip'd forms: .wrz .wrl.gz .x3dvz .x3dz (read too).",
      with_read_limits({
          {"output", "OUT", ""},
          {"from", "EXT", "read IN as the format of extension EXT (step, stl, ...) whatever its name"},
          {"mesh", "",
           "write triangles: every NURBS surface tessellated so that no point of\n"
           "the mesh is farther than the deviation from the exact surface\n"
           "(formats that hold triangles only imply it)"},
          {"deviation", "D",
           "that maximum deviation, in the output unit (default: 0.001 x the\n"
           "bounding-box diagonal)"},
          {"check-areas", "",
           "--mesh: also compare every face's mesh area with its exact area and\n"
           "count the faces that differ by more than a mesh within D may (a fold)"},
          {"display-deviation", "D",
           "NURBS output: uTessellation / vTessellation / trimming-curve counts\n"
           "with which viewers that tessellate uniformly (X_ITE, view3dscene) draw\n"
           "every face within D (default: as --deviation; 0: none written)"},
          {"steps", "N", "instead: uniform tessellation, N steps per knot span (seed 000's method)"},
          {"simplify", "D",
           "NURBS output: remove the knots that faces and 3D curves do not need within\n"
           "D/8 (knot removal; trims kept, so shared edges part by at most D/4, what\n"
           "sewing bridges at D); then the deviation is measured (the original faces\n"
           "meshed within D/4 against the simplified ones) and the meshes at D compared\n"
           "for open edges (an edge opened: redone within D/64, then D/512, else none\n"
           "removed); fails when the deviation exceeds D"},
          {"exact-nurbs", "",
           "every face as the trimmed NURBS of its source, orders, knots, weights and\n"
           "control points unchanged (only DEF/USE sharing applies)"},
          {"units", "U",
           "output lengths in U: mm (default), cm, m, in, kicad (0.1 inch, the unit\n"
           "KiCad's VRML reader assumes); the file records the unit"},
          {"precision", "N",
           "write every number with N significant digits (default: the fewest\n"
           "digits that keep coordinates within 1e-6 of the model size)"},
          {"pretty", "", "VRML/X3D: indented, one field per line"},
          {"euclidean", "",
           "write/read control points as Euclidean points with separate weights\n"
           "(default: homogeneous w*P, the convention of current viewers)"},
          {"self-contained", "", "VRML97: paste the NURBS PROTO implementations into the file"},
          {"compress", "C",
           ".glb: draco (default), meshopt or none. .glb and .drc quantise positions: the\n"
           "mesh is made within 0.7 D and the coarsest grid that moves no vertex by more\n"
           "than 0.3 D is taken, so the decoded mesh stays within D (metres, +Y up in .glb)"},
      }),
      ".cnb (cadnurbs compact binary NURBS, docs/cnb.md): --deviation D is its bound (default 0.001 x the\n"
      "diagonal): control points and trims quantised so that no decoded point moves by more than D.\n"
      "Each body (faces joined by shared edges) is written as its NURBS or as a mesh certified within\n"
      "0.4 D, whichever the file holds in fewer bytes (--exact-nurbs: NURBS always); one line says how\n"
      "many were meshed.\n"
      "A STEP/IGES face that cannot be written as a trimmed NURBS is written as a mesh instead;\n"
      "convert lists each such face and says how many there were.",
  };
  return spec;
}

namespace {

void print_compaction(const std::string& out, const CompactReport& r) {
  std::cout << out << ": compact: " << r.planar_faces << " planar faces as exact polygons in " << r.polygon_meshes
            << " face sets, " << r.untrimmed << " trims that were the domain boundary dropped, " << r.straight_runs
            << " straight trimming runs as polylines, " << r.reparametrised << " knot vectors as small numbers, "
            << r.knots_removed << " trimming-curve knots removed, " << r.instanced << " repeated parts placed as copies\n";
}

// "STL" for "part.stl".
std::string upper_extension(const std::string& path) {
  std::string name = file_extension(path).substr(1);
  for (auto& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

void print_simplified(const std::string& out, const SimplifiedScene& s, const std::string& unit_name) {
  const std::string unit = " " + unit_name;
  const double d = s.max_deviation;
  const auto open = [&](const EdgeCounts& e) {
    return std::to_string(e.boundary) + " open edges (" + number_text(e.boundary_length, 4) + unit + ")";
  };
  std::cout << out << ": simplified within " << number_text(d, 4) << unit << " (faces moved by at most "
            << number_text(s.max_move, 4) << ", " << s.attempts << (s.attempts == 1 ? " attempt" : " attempts") << "; "
            << s.instanced << " repeated parts placed as copies first): " << s.knots.knots_removed << " knots removed ("
            << s.knots.surfaces_changed << " surfaces, " << s.knots.curves_changed << " curves), control points "
            << s.knots.control_points_before << " -> " << s.knots.control_points_after << ", certified deviation "
            << number_text(s.certified_deviation, 4) << unit << " (measured " << number_text(s.measured, 4)
            << " + mesh " << number_text(s.mesh_deviation, 4) << " + copies " << number_text(s.copies_moved, 4)
            << "; curves " << number_text(s.knots.curve_deviation, 4) << "), meshed at " << number_text(d, 4) << ": "
            << open(s.open_before) << " before, " << open(s.open_after) << " after, " << s.unshared_after
            << " unshared edge uses\n";
}

void print_sewing(const std::string& in, const CertifiedMesh& meshed, const std::string& unit_name) {
  const SewingReport& sewing = meshed.sewing;
  std::cout << in << ": sewn at " << meshed.sewing_tolerance.first << " " << unit_name << " (gaps up to "
            << meshed.sewing_tolerance.largest << "; widest bridged " << sewing.widest_gap << "): " << sewing.shared_edges
            << " shared edges, " << sewing.open_pieces << " open boundary pieces, " << sewing.cuts
            << " pieces cut at a neighbour's vertex, " << sewing.polygon_faces << " polygons as faces\n";
}

// The end of the written line: how the mesh was made, if it is one.
std::string how_meshed(const ConversionResult& result, const std::string& unit_name) {
  if (result.steps > 0) return ", uniform " + std::to_string(result.steps) + " steps per span";
  if (!result.mesh) return "";
  const ConversionResult::Mesh& m = *result.mesh;
  const TessellationReport& report = m.report;
  return ", max deviation " + std::to_string(m.deviation) + " " + unit_name +
         (m.quantised ? " (mesh within " + std::to_string(m.tessellated) + ", positions quantised within " +
                            std::to_string(m.quantisation_budget) + ")"
                      : std::string()) +
         "; certified " + std::to_string(report.certified_deviation) + ", " +
         std::to_string(report.uncertified_triangles) + " uncertified triangles, " +
         std::to_string(report.unshared_edge_uses) + " unshared edge uses" +
         (report.loops_without_area > 0
              ? ", " + std::to_string(report.loops_without_area) + " trimming loops thinner than D not meshed"
              : std::string()) +
         (m.check_areas ? ", " + std::to_string(report.faces_beyond_area_allowance) + " faces beyond their area allowance"
                        : std::string());
}

}  // namespace

int run_convert(const std::vector<std::string>& args, const CommandContext& context) {
  const Arguments a = parse_arguments(convert_command_spec(), args);
  if (a.has("help")) {
    std::cout << command_help(convert_command_spec());
    return 0;
  }
  if (a.positional.size() != 1 || !a.has("output")) throw UsageError("needs one input and -o OUT (see --help)");
  ConversionRequest request;
  request.input = a.positional[0];
  request.output = a.value("output");
  const std::string& in = request.input;
  const std::string& out = request.output;
  std::error_code ec;
  if (std::filesystem::equivalent(in, out, ec)) throw UsageError(out + ": output would overwrite the input");
  request.steps = a.integer("steps", 0);
  if (a.has("steps") && request.steps < 1) throw UsageError("--steps must be at least 1");
  request.deviation = a.number("deviation", 0.0);
  if (a.has("deviation") && !(request.deviation > 0)) throw UsageError("--deviation must be positive");
  if (a.has("deviation") && a.has("steps")) throw UsageError("--deviation and --steps exclude each other");
  request.display_deviation = a.number("display-deviation", -1.0);
  if (a.has("display-deviation") && !(request.display_deviation >= 0))
    throw UsageError("--display-deviation must be 0 or more");
  request.simplify = a.number("simplify", 0.0);
  if (a.has("simplify") && !(request.simplify > 0 && std::isfinite(request.simplify)))
    throw UsageError("--simplify must be positive");
  request.precision = a.integer("precision", 0);
  if (a.has("precision") && (request.precision < 1 || request.precision > 17))
    throw UsageError("--precision must be 1 to 17");
  if (a.has("units")) {
    request.unit = length_unit_named(a.value("units"));
    if (!request.unit) throw UsageError("--units: unknown unit '" + a.value("units") + "' (mm, cm, m, in, kicad)");
  }
  output_format(out);  // refuse an unknown output before the work
  request.input_format = a.has("from") ? &named_input_format(a.value("from")) : &input_format(in);
  request.read = scene_read_options(a, context);
  request.mesh = a.has("mesh");
  request.check_areas = a.has("check-areas");
  request.exact_nurbs = a.has("exact-nurbs");
  request.pretty = a.has("pretty");
  request.self_contained = a.has("self-contained");
  if (a.has("compress")) request.compression = a.value("compress");
  check_request(request);

  const LoadedInput input = load_input(request);
  const BrepTranslation& loaded = input.loaded;
  // A part whose size cannot be used fails with its one line, before the reader's notes and repairs.
  checked_diagonal(input.scene, in);
  // A kept scene graph is written as read: what the Scene leaves out is not left out of it, and a face
  // the Scene repairs or leaves out stays as the file wrote it.
  const bool kept = keeps_scene_graph(request);
  if (!kept)
    for (const auto& line : loaded.notes) std::cerr << in << ": " << line << "\n";
  for (const auto& line : loaded.repairs) std::cerr << in << ": " << (kept ? "kept as written: " : "") << line << "\n";
  for (const auto& f : loaded.fallbacks)
    std::cerr << in << ": " << f.node << " face " << f.face_index << " (" << f.surface_type
              << ") written as a mesh: " << f.reason << "\n";
  const std::string& unit_name = input.scene.unit.name;
  ConversionLog log;
  log.simplified = [&](const SimplifiedScene& s) { print_simplified(out, s, unit_name); };
  log.sewn = [&](const CertifiedMesh& meshed) { print_sewing(in, meshed, unit_name); };
  log.compacted = [&](const CompactReport& r) { print_compaction(out, r); };
  log.curves_dropped = [&](int curves) {
    std::cerr << in << ": " << curves << " NURBS curve" << (curves == 1 ? "" : "s") << " left out: "
              << upper_extension(out) << " holds triangles only\n";
  };
  log.coded = [&](const CnbCoding& coding) {
    const double scale = coding.options.quantisation_scale;
    const std::string sewn =
        scale < 1 ? "; control points and trims quantised for D/" + number_text(1 / scale, 3) +
                        ", so that its faces, sewn again on reading, stay joined"
                  : "";
    if (request.exact_nurbs) {
      if (!sewn.empty()) std::cout << out << ": " << coding.bytes.size() << " bytes" << sewn << "\n";
      return;
    }
    const CodingChoiceReport& r = coding.choice;
    const char* made_from[] = {"", "", "", ", meshed from the faces before compaction",
                               ", merged into one mesh per colour"};  // CodingChoiceReport::Whole's order
    std::cout << out << ": " << r.bodies_meshed << " of " << r.bodies << " bodies (" << r.faces_meshed << " faces, "
              << r.polygons_meshed << " polygons) written as certified meshes within "
              << number_text(r.certified_deviation, 3) << " " << unit_name << made_from[static_cast<int>(r.chosen)]
              << ", " << r.bytes() << " bytes (NURBS as they are: " << r.as_is_bytes << ")" << sewn;
    if (coding.written.piece_copies > 0)
      std::cout << "; " << coding.written.piece_copies << " mesh pieces coded as copies of others";
    std::cout << "\n";
  };
  const ConversionResult result = convert_loaded(request, input, log);
  if (result.scene_graph) {
    const auto& g = *result.scene_graph;
    for (const auto& line : g.notes) std::cerr << out << ": " << line << "\n";
    std::cout << out << ": the whole scene graph kept: " << g.nodes << " nodes of " << g.kinds << " kinds, " << g.routes
              << " ROUTEs, " << g.protos << " PROTO declarations\n";
  }
  const SceneCounts& c = result.counts;
  std::cout << out << ": " << c.surfaces << " NURBS surfaces, " << c.polygon_meshes << " polygon sets ("
            << c.polygons << " polygons), " << c.meshes << " meshes (" << c.mesh_triangles << " triangles"
            << how_meshed(result, unit_name) << ")\n";
  if (loaded.face_count > 0)
    std::cout << in << ": " << loaded.face_count << " faces: " << loaded.face_count - int(loaded.fallbacks.size())
              << " as trimmed NURBS, " << loaded.fallbacks.size() << " fell back to a mesh\n";
  return 0;
}

}  // namespace cadnurbs
