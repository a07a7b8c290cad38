#include "converters/part_measurement.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <unistd.h>

#include "analysis/measure/measure_deviation.hpp"
#include "analysis/measure/mesh_distance.hpp"
#include "report/smallest_compressed_mesh.hpp"
#include "report/nurss_figures.hpp"
#include "formats/nurss/nurss_text.hpp"
#include "report/report_formats.hpp"
#include "report/storage_crossover.hpp"
#include "analysis/mesh/largest_corner_move.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "converters/cnb_coding.hpp"
#include "converters/file_formats.hpp"
#include "converters/subdivision_fit_measurement.hpp"
#include "converters/conversion.hpp"
#include "converters/conversion_record.hpp"
#include "converters/scene_preparation.hpp"
#include "core/bounding_box.hpp"
#include "core/geometry_error.hpp"
#include "core/number_format.hpp"
#include "core/world_scale.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"
#include "formats/draco/draco_mesh_codec.hpp"
#include "formats/meshopt/meshopt_mesh_codec.hpp"
#include "formats/obj/control_mesh_obj.hpp"

namespace cadnurbs {

namespace {

namespace fs = std::filesystem;

// The NURBS files the report writes: one row per representation (what convert writes with these options).
struct NurbsFile {
  const char* key;
  const char* label;
  const char* extension;
  bool compact;
};
constexpr NurbsFile kNurbsFiles[] = {
    {"wrl-compact", "VRML97 NURBS, compact", ".wrl", true},
    {"wrl-exact", "VRML97 NURBS, exact (--exact-nurbs)", ".wrl", false},
    {"x3dv-compact", "X3D classic NURBS, compact", ".x3dv", true},
    {"x3dv-exact", "X3D classic NURBS, exact (--exact-nurbs)", ".x3dv", false},
};

// The mesh files: the certified mesh at D as written by the mesh writers.
struct MeshFile {
  const char* key;
  const char* label;
  const char* extension;
  const char* input_label;  // when the part is given as a mesh: the input itself, written again
};
constexpr MeshFile kMeshFiles[] = {
    {"wrl-mesh", "VRML97 IndexedFaceSet at D", ".wrl", "VRML97 IndexedFaceSet of the input"},
    {"stl-mesh", "binary STL at D", ".stl", "binary STL of the input"},
};

// The compressed meshes: the smallest encoding within D (report/smallest_compressed_mesh), written as the codec's
// own file.
struct EncodedMeshFile {
  MeshCodec codec;
  const char* key;
  const char* label;
  const char* extension;
  TriangleMesh (*decode)(const std::string& bytes, const std::string& name);
};
const EncodedMeshFile kEncodedMeshFiles[] = {
    {MeshCodec::draco, "draco", "Draco, coarsest quantisation within D", ".drc", decode_draco_mesh},
    {MeshCodec::meshopt, "meshopt", "meshoptimizer codecs (gltfpack's way) within D", ".meshopt", decode_meshopt_mesh},
};

// The D values of the storage-against-accuracy curve, as fractions of the bounding-box diagonal.
constexpr double kCurveFractions[] = {1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5};
// A curve point whose mesh would exceed this many triangles is left out (its memory, not its truth).
constexpr long kCurveTriangleLimit = 4'000'000;
// Draco and meshopt are tried (three tessellations each, and a measurement) up to this many triangles.
constexpr long kCurveEncodingLimit = 200'000;

// A folder that is removed when the measurement ends, unless the user named it.
class Folder {
 public:
  explicit Folder(const std::string& named) : keep_(!named.empty()) {
    static std::atomic<int> counter{0};
    path_ = keep_ ? fs::path(named)
                  : fs::temp_directory_path() /
                        ("cadnurbs-report-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(path_);
  }
  ~Folder() {
    std::error_code ec;
    if (!keep_) fs::remove_all(path_, ec);
  }
  fs::path file(const std::string& stem, const std::string& suffix) const { return path_ / (stem + suffix); }

 private:
  bool keep_;
  fs::path path_;
};

// What convert writes `path` with for this part (the report measures convert's files): its options for
// the part's input and `scene` (the part as read), with `deviation` as --deviation (0: not given).
SceneWriteOptions convert_options(const PartRecord& record, const Scene& scene, const fs::path& path,
                                  double deviation = 0) {
  ConversionRequest request;
  request.input = record.input;
  request.output = path.string();
  request.deviation = deviation;
  return scene_write_options(request, scene, record.diagonal);
}

// Runs `write_and_measure` for the representation `label` written at `path`. A format that cannot hold
// this part (VRML97 has no PROTO for a NurbsCurve node yet) costs that representation, not the record:
// the failure becomes a note naming the format, never the temporary file, and false is returned.
template <class Work>
bool measured_or_noted(PartRecord& record, const std::string& label, const fs::path& path, Work&& write_and_measure) {
  try {
    write_and_measure();
    return true;
  } catch (const std::exception& e) {
    record.warnings.push_back(label + ": not measured: " + record_error(e.what(), path.string()));
    return false;
  }
}

// Size of the file and of its gzip'd form; returns the file's bytes for the reader that reads it back.
std::string measure_bytes(const fs::path& path, RepresentationFigures& figures) {
  std::string bytes = read_file(path.string());
  figures.bytes = static_cast<long>(bytes.size());
  figures.gzip_bytes = is_gzip(bytes) ? figures.bytes : static_cast<long>(gzip(bytes).size());
  return bytes;
}

// The mesh a mesh file holds, welded (shared vertices counted once, as an indexed mesh stores them).
TriangleMesh read_back_mesh(const fs::path& path) { return weld_exact(scene_triangles(read_scene(path.string()))); }

// Floats and integers of a mesh file as read back: every shape's own vertex list and its distinct normals
// (an IndexedFaceSet stores each distinct normal once and indexes it per corner), or STL's soup.
void count_mesh_file(const Scene& read_back, bool soup, RepresentationFigures& f) {
  for_each_shape(read_back, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry);
    if (!mesh) return;
    const long triangles = static_cast<long>(mesh->triangles.size());
    if (soup) {
      f.floats += 12 * triangles;
      return;
    }
    std::set<std::array<double, 3>> normals;
    for (const auto& n : mesh->corner_normals) normals.insert({n.x(), n.y(), n.z()});
    f.floats += 3 * static_cast<long>(mesh->positions.size() + normals.size());
    f.integers += (mesh->corner_normals.empty() ? 3 : 6) * triangles;
  });
}

// The certified mesh at D (`meshed`, of `faces`; `written` = its triangles in world coordinates,
// `certificate` = its certificate stretched by the placements) written as `file`. The deviation is a bound
// when every triangle is certified: the certificate plus the largest move of a corner between the mesh written and the file read back
// (analysis/mesh/largest_corner_move). With uncertified triangles, each face's triangles are measured
// against that face (sampled). `as_read` gets the file's triangles in world coordinates, unwelded.
RepresentationFigures mesh_figures(const MeshFile& file, const fs::path& path, const CertifiedMesh& meshed,
                                   const Scene& faces, const TriangleMesh& written, double certificate,
                                   TriangleMesh& as_read) {
  RepresentationFigures f{file.key, file.label, RepresentationKind::mesh, 0, 0, 0, 0, 0, ""};
  measure_bytes(path, f);
  const Scene read_back = read_scene(path.string());
  count_mesh_file(read_back, std::string(file.extension) == ".stl", f);
  as_read = scene_triangles(read_back);
  const std::optional<double> moved = largest_corner_move(written, as_read);
  if (!moved) {
    f.deviation_basis = "not known: the file read back has " + std::to_string(as_read.triangles.size()) +
                        " triangles where " + std::to_string(written.triangles.size()) + " were written";
  } else if (meshed.report.uncertified_triangles == 0) {
    f.deviation = certificate + *moved;
    f.deviation_kind = DeviationKind::bound;
    f.deviation_basis = "bound: the tessellator's certificate " + report_number(certificate) +
                        " plus the largest vertex move through the file " + report_number(*moved);
  } else {
    f.deviation = measure_deviation_by_face(as_read, meshed.meshes, faces).overall.max;
    f.deviation_basis = "measured face by face after read-back (two-sided, sampled): " +
                        std::to_string(meshed.report.uncertified_triangles) + " triangles are not certified";
  }
  return f;
}

// Our binary NURBS (.cnb) of the compact form (moved by at most `tolerance`) within D, each body coded the
// cheapest way (converters/cnb_coding: NURBS, or a certified mesh of it or of the part `scene`), as
// `convert --deviation D` writes it, read back. The deviation is the writer's bound (formats/cnb/
// cnb_quantisation.hpp: control points, trims and weights, and the meshes' certificate) plus the compact
// form's.
void add_compact_binary(PartRecord& record, const Scene& scene, const Scene& compact, double tolerance,
                        const Folder& folder, const std::string& stem) {
  const fs::path path = folder.file(stem + "-compact", ".cnb");
  const CnbCoding coding = cnb_coding(compact, record.deviation, &scene);
  const CnbWriteReport& written = coding.written;
  write_file_atomically(path.string(), coding.bytes);
  RepresentationFigures f{"cnb", "cadnurbs binary NURBS (.cnb) within D", RepresentationKind::nurbs, 0, 0, 0, 0, 0, ""};
  const Scene decoded = read_cnb(measure_bytes(path, f), path.string());
  const NurbsStorage storage = nurbs_storage(decoded);
  f.floats = storage.total_floats();
  f.integers = storage.polygon_corners;
  f.deviation = written.deviation_bound() + tolerance;
  f.deviation_kind = DeviationKind::bound;
  f.deviation_basis = "bound: the quantisation's " + report_number(written.deviation_bound()) +
                      " plus the written precision of the compact form" + meshed_bodies_basis(coding.choice);
  record.representations.push_back(f);
}

// The quadratic NURSS of the part's order-3 nets with the lids as n-gon faces (analysis/nurss), where the
// part is made of such nets (the stair cappings): its control mesh written as a .nurss text file and read
// back, and its limit mesh at the fewest levels within D away from the n-gons, written as an
// IndexedFaceSet to look at; the deviation given is the whole limit mesh's, measured against the NURBS.
void add_nurss(PartRecord& record, const Scene& scene, const Folder& folder, const std::string& stem) {
  const auto figures = nurss_figures(scene, record.deviation);
  if (!figures) return;  // not a part of quadratic nets: no NURSS row
  const fs::path path = folder.file(stem, ".nurss");
  write_file_atomically(path.string(), figures->text);
  RepresentationFigures f{"nurss", "quadratic NURSS control mesh (.nurss)", RepresentationKind::nurss, 0, 0, 0, 0, 0, ""};
  const NurssStorage storage = nurss_storage(read_nurss_text(measure_bytes(path, f), path.string()));
  f.floats = storage.floats;
  f.integers = storage.connectivity_integers;
  f.deviation = figures->whole.overall.max;
  // One subdivision surface stands for several faces, so it is measured against them together.
  f.deviation_basis = "measured (sampled): limit mesh at " + std::to_string(figures->levels) +
                      " levels against the NURBS; " +
                      report_number(figures->away_from_ngons.mesh_to_surface.max) + " away from the n-gon faces";
  record.representations.push_back(f);
  Scene limit;
  limit.unit = scene.unit;
  limit.root.name = stem + "-nurss-limit";
  limit.root.shapes.push_back({"limit", figures->limit_mesh, std::nullopt});
  const fs::path limit_path = folder.file(stem + "-nurss-limit", ".wrl");
  write_scene(limit_path.string(), limit, convert_options(record, scene, limit_path));
  if (!figures->within_max_deviation || f.deviation > record.deviation)
    record.warnings.push_back("NURSS limit mesh: " + report_number(f.deviation) + " from the NURBS after " +
                              std::to_string(figures->levels) + " levels (" + f.deviation_basis + ")");
}

// Draco and meshoptimizer files of the mesh within D, read back and decoded; the deviation is the bound
// encode_mesh_within replays and checks on the decoded mesh. A scene the encoder refuses (faces that fell back to meshes
// have nothing exact to be measured against) gets a warning instead.
void add_encoded_meshes(PartRecord& record, const Scene& faces, const Folder& folder, const std::string& stem) {
  std::vector<MeshCodec> codecs;
  for (const auto& file : kEncodedMeshFiles) codecs.push_back(file.codec);
  std::vector<MeshEncodingFigures> encoded;
  MeshEncodingOptions options;
  options.measure_after_decoding = false;  // the bound is replayed and checked after decoding
  try {
    encoded = encode_mesh_within(faces, record.deviation, codecs, options);
  } catch (const std::exception& e) {
    record.warnings.push_back(std::string("compressed meshes not measured: ") + e.what());
    return;
  }
  for (std::size_t i = 0; i < encoded.size(); ++i) {
    const EncodedMeshFile& file = kEncodedMeshFiles[i];
    const fs::path path = folder.file(stem + "-mesh", file.extension);
    write_file_atomically(path.string(), encoded[i].bytes);
    RepresentationFigures f{file.key, file.label, RepresentationKind::mesh, 0, 0, 0, 0, 0, ""};
    const TriangleMesh decoded = file.decode(measure_bytes(path, f), path.string());
    const MeshStorage storage = mesh_storage(decoded);
    f.floats = storage.indexed_floats;
    f.integers = storage.indexed_integers;
    f.deviation = encoded[i].deviation_bound;
    f.deviation_kind = DeviationKind::bound;
    f.deviation_basis = "bound: the tessellator's certificate " + report_number(encoded[i].certified_deviation) +
                        " plus the largest vertex move of the " + std::to_string(encoded[i].position_bits) +
                        "-bit quantisation " + report_number(encoded[i].displacement) +
                        " (replayed, and checked after decoding)";
    record.representations.push_back(f);
  }
}

// Bytes against D: the certified mesh as IndexedFaceSet at every D of kCurveFractions; Draco and meshopt
// within the same D while the mesh is small enough to encode and measure in reasonable time; our .cnb of
// the compact form within the same D. Then, for each mesh encoding, the D below which it costs more than
// the .cnb at that D (the curves are interpolated log-log between measured points).
void add_curve(PartRecord& record, const BrepTranslation& loaded, const Scene& scene, const Scene& compact,
               const Folder& folder, const std::string& stem) {
  for (double fraction : kCurveFractions) {
    const double d = fraction * record.diagonal;
    const CertifiedMesh meshed = certified_mesh(loaded, scene, d);
    if (meshed.report.triangles > kCurveTriangleLimit) {
      record.warnings.push_back("storage curve stops above D = " + std::to_string(d) + " " + record.unit + ": " +
                                std::to_string(meshed.report.triangles) + " triangles");
      break;
    }
    const fs::path path = folder.file(stem + "-curve", ".wrl");
    write_scene(path.string(), meshed.meshes, convert_options(record, scene, path, d));
    RepresentationFigures f;
    measure_bytes(path, f);
    const MeshStorage storage = mesh_storage(read_back_mesh(path));
    record.curve.push_back({"wrl-mesh", d, f.bytes, f.gzip_bytes, storage.indexed_floats});
    const long cnb_bytes = static_cast<long>(cnb_coding(compact, d, &scene).bytes.size());
    record.curve.push_back({"cnb", d, cnb_bytes, cnb_bytes, 0});
    if (meshed.report.triangles > kCurveEncodingLimit) continue;
    try {
      const auto encoded =
          encode_mesh_within(meshed.sewn ? meshed.faces : scene, d, {MeshCodec::draco, MeshCodec::meshopt});
      for (const auto& e : encoded)
        record.curve.push_back({mesh_codec_name(e.codec), d, e.raw_bytes, e.gzip_bytes, 3 * e.vertices});
    } catch (const std::exception&) {
      // the at-D rows already say why compressed meshes of this part cannot be measured
    }
  }
  std::map<std::string, std::vector<BytesAtDeviation>> curves;
  for (const auto& p : record.curve) curves[p.key].push_back({p.deviation, double(std::min(p.bytes, p.gzip_bytes))});
  const RepresentationFigures* cnb_at_d = find_representation(record, "cnb");
  if (!cnb_at_d) return;
  for (const char* key : {"wrl-mesh", "draco", "meshopt"}) {
    if (!curves.count(key)) continue;
    const Crossover crossing = storage_crossover(curves[key], double(cnb_at_d->bytes));
    CrossoverFigure figure{key, "cnb", cnb_at_d->bytes};
    if (crossing.deviation) figure.deviation = *crossing.deviation;
    figure.mesh_larger_everywhere = crossing.mesh_larger_everywhere;
    record.crossovers.push_back(figure);
  }
}

// A part given as a mesh (STL): what users have (the mesh as written, indexed and as STL, read back and
// compared with the input) against the Loop subdivision surface fitted within D (analysis/subdivision_fit):
// its control mesh with tags as OBJ, read back; the deviation is the limit surface's, two-sided, against
// the input; the limit mesh is written as an IndexedFaceSet to look at.
void measure_mesh_input(PartRecord& record, const Scene& scene, const Folder& folder, const std::string& stem,
                        PartViews* views) {
  const TriangleMesh input = scene_triangles(scene);
  if (input.triangles.empty()) throw std::invalid_argument("no NURBS surfaces and no triangles to measure");
  record.mesh = mesh_storage(weld_exact(input));
  for (const auto& file : kMeshFiles) {
    const fs::path path = folder.file(stem + "-mesh", file.extension);
    write_scene(path.string(), scene, convert_options(record, scene, path));
    RepresentationFigures f{file.key, file.input_label, RepresentationKind::mesh, 0, 0, 0, 0, 0, ""};
    measure_bytes(path, f);
    const Scene read_back = read_scene(path.string());
    count_mesh_file(read_back, std::string(file.extension) == ".stl", f);
    const TriangleMesh as_read = scene_triangles(read_back);
    if (const auto moved = largest_corner_move(input, as_read)) {
      f.deviation = *moved;
      f.deviation_kind = DeviationKind::bound;
      f.deviation_basis = "bound: the largest vertex move through the file";
    } else {
      f.deviation = mesh_distance(as_read, input).overall.max;
      f.deviation_basis = "measured (sampled, two-sided) against the input mesh: the file did not keep its triangles";
    }
    record.representations.push_back(f);
  }

  SubdivisionFitRequest request;
  request.tolerance = record.deviation;
  request.source = record.input;
  request.control_vertices = std::max(4, std::min(request.control_vertices, static_cast<int>(record.mesh.vertices) / 2));
  const SubdivisionFitMeasure fit = measure_subdivision_fit(input, request);
  const fs::path path = folder.file(stem + "-loop-control", ".obj");
  write_control_mesh_obj(path.string(), fit.control);
  RepresentationFigures f{"loop", "Loop subdivision control mesh with crease tags (.obj)", RepresentationKind::loop,
                          0, 0, 0, 0, 0, ""};
  const SubdivisionControlMesh read_back = parse_control_mesh_obj(measure_bytes(path, f), path.string());
  f.floats = 3L * static_cast<long>(read_back.positions.size());
  f.integers = 3L * static_cast<long>(read_back.triangles.size()) + 2L * static_cast<long>(read_back.crease_edges.size()) +
               static_cast<long>(read_back.corner_vertices.size());
  f.deviation = fit.limit_distance.max;
  f.deviation_basis = "measured (sampled): limit surface (" + std::to_string(request.levels) + " levels) against the input, two-sided, RMS " +
                      report_number(fit.limit_distance.rms) + "; a quadric decimation with as many vertices: RMS " +
                      report_number(fit.qem_distance.rms) + ", max " + report_number(fit.qem_distance.max);
  record.representations.push_back(f);
  if (!fit.tolerance_met)
    record.warnings.push_back("Loop fit: not within D at its samples after " + std::to_string(fit.rounds) + " rounds");
  Scene limit;
  limit.unit = scene.unit;
  limit.root.name = stem + "-loop-limit";
  limit.root.shapes.push_back({"limit", fit.limit, std::nullopt});
  const fs::path limit_path = folder.file(stem + "-loop-limit", ".wrl");
  write_scene(limit_path.string(), limit, convert_options(record, scene, limit_path));
  if (views) {
    const fs::path mesh_view = folder.file(stem + "-mesh", ".x3dv");
    write_scene(mesh_view.string(), scene, convert_options(record, scene, mesh_view));
    views->mesh_x3dv = read_file(mesh_view.string());
  }
}

// The compact X3D NURBS of the scene with knots removed within `simplify` (convert --simplify): its
// deviation is simplified_scene's (sampled face by face) plus the written precision. When the certificate exceeds
// `simplify` (convert would refuse), the row is left out with a note.
void add_simplified(PartRecord& record, const Scene& scene, double tolerance, double simplify, const Folder& folder,
                    const std::string& stem) {
  const std::string label = "X3D classic NURBS, compact, simplified (--simplify " + message_number(simplify) + ")";
  const fs::path path = folder.file(stem + "-simplified", ".x3dv");
  RepresentationFigures f{"x3dv-simplified", label, RepresentationKind::nurbs, 0, 0, 0, 0, 0, ""};
  NurbsStorage read_back;
  SimplifiedScene simplified;
  const bool written = measured_or_noted(record, label, path, [&] {
    simplified = simplified_scene(scene, simplify, tolerance);
    if (simplified.certified_deviation > simplify)
      throw GeometryError("simplify", "the certified deviation " + message_number(simplified.certified_deviation) +
                                          " exceeds " + message_number(simplify));
    write_scene(path.string(), compact_scene(simplified.scene, tolerance), convert_options(record, scene, path));
    measure_bytes(path, f);
    read_back = nurbs_storage(read_scene(path.string()));
  });
  if (!written) return;
  f.floats = read_back.total_floats();
  f.integers = read_back.polygon_corners;
  f.deviation = simplified.certified_deviation + tolerance;
  // simplified_scene samples each changed face against its certified mesh: measured, face by face.
  f.deviation_basis = "measured face by face (sampled): " + std::to_string(simplified.knots.knots_removed) +
                      " knots removed, each changed face's mesh within D/4 against the face simplified, plus "
                      "that mesh's certificate and the written precision";
  record.representations.push_back(f);
}

PartRecord measure(const std::string& input, const BrepTranslation& loaded, const PartMeasurementOptions& options,
                   PartViews* views) {
  PartRecord record = conversion_record(input, loaded);
  const Scene& scene = loaded.scene;
  record.deviation = options.deviation_mm / scene.unit.millimetres;
  if (!(record.deviation > 0) || !std::isfinite(record.deviation))
    throw std::invalid_argument("the maximum deviation must be a positive number");
  if (record.nurbs.surfaces == 0) {
    measure_mesh_input(record, scene, Folder(options.files_folder), fs::path(input).stem().string(), views);
    return record;
  }
  const double tolerance = written_tolerance(scene, 0);
  const Scene compact = compact_scene(scene, tolerance);
  record.compact_nurbs = nurbs_storage(compact);

  const Folder folder(options.files_folder);
  const std::string stem = fs::path(input).stem().string();
  for (const auto& file : kNurbsFiles) {
    const fs::path path = folder.file(stem + (file.compact ? "-compact" : "-exact"), file.extension);
    RepresentationFigures f{file.key, file.label, RepresentationKind::nurbs, 0, 0, 0, 0, 0, ""};
    NurbsStorage read_back;
    const bool written = measured_or_noted(record, file.label, path, [&] {
      write_scene(path.string(), file.compact ? compact : scene, convert_options(record, scene, path));
      measure_bytes(path, f);
      read_back = nurbs_storage(read_scene(path.string()));
    });
    if (!written) continue;
    f.floats = read_back.total_floats();
    f.integers = read_back.polygon_corners;
    f.deviation = file.compact ? tolerance : 0.5 * tolerance;
    f.deviation_kind = DeviationKind::bound;
    f.deviation_basis = file.compact ? "bound: nothing moved by more than the written precision"
                                     : "bound: half the written precision (rounding)";
    record.representations.push_back(f);
  }

  if (options.simplify_mm > 0) add_simplified(record, scene, tolerance, options.simplify_mm / scene.unit.millimetres, folder, stem);
  add_compact_binary(record, scene, compact, tolerance, folder, stem);
  add_nurss(record, scene, folder, stem);

  const CertifiedMesh meshed = certified_mesh(loaded, scene, record.deviation);
  record.mesh_certified_deviation = meshed.report.certified_deviation;
  if (meshed.report.uncertified_triangles > 0)
    record.warnings.push_back(std::to_string(meshed.report.uncertified_triangles) +
                              " triangles of the mesh at D could not be certified");
  const TriangleMesh mesh_written = scene_triangles(meshed.meshes);
  const double mesh_certificate = largest_world_scale(meshed.meshes) * meshed.report.certified_deviation;
  for (const auto& file : kMeshFiles) {
    const fs::path path = folder.file(stem + "-mesh", file.extension);
    TriangleMesh as_read;
    const bool written = measured_or_noted(record, file.label, path, [&] {
      write_scene(path.string(), meshed.meshes, convert_options(record, scene, path, record.deviation));
      record.representations.push_back(
          mesh_figures(file, path, meshed, meshed.sewn ? meshed.faces : scene, mesh_written, mesh_certificate, as_read));
    });
    // The indexed figures: the first file's mesh (the IndexedFaceSet) with its shared vertices welded.
    if (written && record.mesh.vertices == 0) record.mesh = mesh_storage(weld_exact(as_read));
  }
  add_encoded_meshes(record, meshed.sewn ? meshed.faces : scene, folder, stem);
  if (views) {
    const fs::path nurbs_view = folder.file(stem + "-compact", ".x3dv");
    if (fs::exists(nurbs_view)) views->nurbs_x3dv = read_file(nurbs_view.string());
    const fs::path mesh_view = folder.file(stem + "-mesh", ".x3dv");
    write_scene(mesh_view.string(), meshed.meshes, convert_options(record, scene, mesh_view, record.deviation));
    views->mesh_x3dv = read_file(mesh_view.string());
  }
  if (options.curve) add_curve(record, loaded, scene, compact, folder, stem);
  return record;
}

// `work`'s record, or a failed record with the one-line reason of whatever it threw.
template <class Work>
PartRecord record_or_failure(const std::string& input, PartViews* views, Work&& work) {
  try {
    return work();
  } catch (const std::exception& e) {
    PartRecord failed;
    failed.input = input;
    failed.failed = true;
    failed.error = record_error(e.what(), input);
    if (views) *views = {};
    return failed;
  }
}

}  // namespace

PartRecord measure_part(const std::string& input, const PartMeasurementOptions& options, PartViews* views) {
  return record_or_failure(input, views, [&] {
    const BrepTranslation loaded =
        options.format ? load_scene_as(input, *options.format, options.read) : load_scene(input, options.read);
    return measure(input, loaded, options, views);
  });
}

PartRecord measure_loaded_part(const std::string& input, const BrepTranslation& loaded,
                               const PartMeasurementOptions& options, PartViews* views) {
  return record_or_failure(input, views, [&] { return measure(input, loaded, options, views); });
}

}  // namespace cadnurbs
