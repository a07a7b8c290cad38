#include "report/smallest_compressed_mesh.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <variant>

#include "analysis/mesh/oriented_triangle_keys.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "analysis/mesh/weld_vertices.hpp"
#include "core/flatten_transforms.hpp"
#include "core/geometry_error.hpp"
#include "formats/common/gzip.hpp"
#include "formats/draco/draco_mesh_codec.hpp"
#include "formats/meshopt/meshopt_mesh_codec.hpp"

namespace cadnurbs {

namespace {

const char* const kEntity = "mesh encoding";

std::vector<Eigen::Vector3d> quantised_positions(const TriangleMesh& mesh, MeshCodec codec, int bits) {
  return codec == MeshCodec::draco ? draco_quantised_positions(mesh, bits) : meshopt_quantised_positions(mesh, bits);
}

// Whether the quantised positions `q` (mesh.positions' order) put two corners of a triangle on one grid
// point. Such a triangle becomes a segment, which Draco drops (a repeated index); where a thin feature
// (a lead, a pin) collapses whole, its neighbours collapse too and nothing covers it any more: the
// decoded mesh would leave the bound (measured: 1.2 mm at D = 1 mm on TQFP-32's leads). So no triangle
// may collapse.
bool collapses_a_triangle(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& q) {
  for (const auto& t : mesh.triangles)
    if (q[t[0]] == q[t[1]] || q[t[1]] == q[t[2]] || q[t[2]] == q[t[0]]) return true;
  return false;
}

// Largest distance from a vertex of `mesh` to its quantised position `moved` (same order).
double largest_displacement(const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& moved) {
  double largest = 0;
  for (size_t i = 0; i < moved.size(); ++i) largest = std::max(largest, (moved[i] - mesh.positions[i]).norm());
  return largest;
}

// One candidate: a certified tessellation encoded at its coarsest bits, decoded and checked.
struct Candidate {
  MeshEncodingFigures figures;
  TriangleMesh decoded;
};

Candidate encode_candidate(const TriangleMesh& mesh, double max_deviation, double fraction, double certified,
                           MeshCodec codec, const MeshEncodingOptions& options) {
  Candidate out;
  MeshEncodingFigures& f = out.figures;
  f.codec = codec;
  f.max_deviation = max_deviation;
  f.fraction = fraction;
  f.certified_deviation = certified;
  f.displacement_budget = max_deviation - certified;
  const QuantisationChoice choice = coarsest_quantisation(mesh, codec, f.displacement_budget);
  if (choice.bits == 0)
    throw GeometryError(kEntity, std::string(mesh_codec_name(codec)) + " quantisation cannot keep vertices within " +
                                     std::to_string(f.displacement_budget) + " even at 30 bits");
  f.position_bits = choice.bits;
  f.displacement = choice.displacement;
  f.deviation_bound = f.certified_deviation + f.displacement;

  const std::string name = std::string(mesh_codec_name(codec)) + " mesh";
  f.bytes = codec == MeshCodec::draco ? encode_draco_mesh(mesh, f.position_bits, options.draco_speed)
                                      : encode_meshopt_mesh(mesh, f.position_bits);
  f.raw_bytes = static_cast<long>(f.bytes.size());
  f.gzip_bytes = static_cast<long>(gzip(f.bytes).size());
  out.decoded = codec == MeshCodec::draco ? decode_draco_mesh(f.bytes, name) : decode_meshopt_mesh(f.bytes, name);
  f.vertices = static_cast<long>(out.decoded.positions.size());
  f.triangles = static_cast<long>(out.decoded.triangles.size());
  // The bound rests on this: the decoded triangles are ours, each corner where the replay put it.
  if (oriented_triangle_keys(out.decoded.positions, out.decoded.triangles) !=
      oriented_triangle_keys(quantised_positions(mesh, codec, f.position_bits), mesh.triangles))
    throw GeometryError(kEntity, "the decoded " + name + " is not the quantised tessellation");
  return out;
}

}  // namespace

const char* mesh_codec_name(MeshCodec codec) { return codec == MeshCodec::draco ? "draco" : "meshopt"; }

TriangleMesh certified_world_mesh(const Scene& scene, double deviation, TessellationReport* report) {
  return weld_exact(scene_triangles(tessellate_to_deviation(flatten_transforms(scene), deviation, report)));
}

TriangleMesh with_hair_apart_corners_welded(const TriangleMesh& mesh, MeshCodec codec, double budget, double* moved) {
  *moved = 0;
  if (coarsest_quantisation(mesh, codec, budget).bits > 0) return mesh;
  WeldReport weld;
  TriangleMesh welded = weld_vertices(mesh, 0.01 * budget, &weld);
  if (welded.triangles.empty()) throw GeometryError(kEntity, "the tessellation has no triangles once welded");
  *moved = weld.largest_merge_distance;
  return welded;
}

double quantisation_displacement(const TriangleMesh& mesh, MeshCodec codec, int bits) {
  return largest_displacement(mesh, quantised_positions(mesh, codec, bits));
}

QuantisationChoice coarsest_quantisation(const TriangleMesh& mesh, MeshCodec codec, double budget) {
  // Every bit count in turn: the exact displacement need not fall monotonically with the bits.
  for (int bits = 1; bits <= 30; ++bits) {
    const std::vector<Eigen::Vector3d> q = quantised_positions(mesh, codec, bits);  // one replay serves both tests
    const double d = largest_displacement(mesh, q);
    if (d <= budget && !collapses_a_triangle(mesh, q)) return {bits, d};
  }
  return {};
}

std::vector<MeshEncodingFigures> encode_mesh_within(const Scene& scene, double max_deviation,
                                                    const std::vector<MeshCodec>& codecs,
                                                    const MeshEncodingOptions& options) {
  if (!(max_deviation > 0)) throw GeometryError(kEntity, "maximum deviation must be positive");
  if (options.fractions.empty()) throw GeometryError(kEntity, "no tessellation fractions");
  for (double f : options.fractions)
    if (!(f > 0 && f < 1)) throw GeometryError(kEntity, "tessellation fraction " + std::to_string(f) + " outside (0, 1)");
  bool surfaces = false;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (std::holds_alternative<TriangleMesh>(shape.geometry) || std::holds_alternative<PolygonMesh>(shape.geometry))
      throw GeometryError(kEntity, "shape '" + display_name(shape) +
                                       "' is a mesh, with no exact surface to measure the encoding against");
    surfaces = surfaces || std::holds_alternative<TrimmedSurface>(shape.geometry);
  });
  if (!surfaces) throw GeometryError(kEntity, "the scene has no surfaces");
  if (codecs.empty()) return {};

  std::vector<std::optional<Candidate>> best(codecs.size());
  auto size = [](const MeshEncodingFigures& f) { return f.codec == MeshCodec::draco ? f.raw_bytes : f.gzip_bytes; };
  for (double fraction : options.fractions) {
    const double target = fraction * max_deviation;
    TessellationReport report;
    TriangleMesh mesh = certified_world_mesh(scene, target, &report);
    if (report.uncertified_triangles > 0)
      throw GeometryError(kEntity, std::to_string(report.uncertified_triangles) + " triangles of the tessellation at " +
                                       std::to_string(target) + " are not certified");
    if (mesh.triangles.empty()) throw GeometryError(kEntity, "the tessellation has no triangles");
    // Trim chords are sampled to the target, which the triangle bounds in the report do not include.
    double certified = std::max(report.certified_deviation, target);
    // A quarter of the KiCad library's parts have corners a hair apart; the move joins the bound.
    double moved = 0;
    mesh = with_hair_apart_corners_welded(mesh, codecs.front(), max_deviation - certified, &moved);
    certified += moved;
    for (size_t i = 0; i < codecs.size(); ++i) {
      Candidate c = encode_candidate(mesh, max_deviation, fraction, certified, codecs[i], options);
      if (!best[i] || size(c.figures) < size(best[i]->figures)) {
        c.figures.certified_mesh = mesh;
        best[i] = std::move(c);
      }
    }
  }
  std::vector<MeshEncodingFigures> out;
  for (auto& b : best) {
    if (options.measure_after_decoding) b->figures.measured = measure_deviation(b->decoded, scene, options.measure);
    out.push_back(std::move(b->figures));
  }
  return out;
}

MeshEncodingFigures encode_mesh_within(const Scene& scene, double max_deviation, MeshCodec codec,
                                       const MeshEncodingOptions& options) {
  return std::move(encode_mesh_within(scene, max_deviation, std::vector<MeshCodec>{codec}, options).front());
}

}  // namespace cadnurbs
