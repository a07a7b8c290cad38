#pragma once
// The smallest compressed mesh (Draco, or meshoptimizer + gzip) of a scene's trimmed NURBS whose
// decoded mesh lies within D of the exact surfaces, with a bound that holds and a measurement after
// decoding.
//
// Method, for each tessellation fraction f (options.fractions):
//  1. tessellate_to_deviation at f * D in world coordinates (flatten_transforms first, so D is a world
//     distance), all faces as one mesh, weld_exact (shared edges carry bit-identical vertices);
//     certified deviation c = f * D (the tessellator's target: its trim chords are sampled to it; its
//     triangle bounds, reported separately, are below it).
//  2. the coarsest position bits whose largest vertex displacement is <= D - c (>= (1 - f) * D) and that
//     collapse no triangle (two corners on one grid point). The
//     displacement is exact, not estimated: the codec's quantisation is replayed vertex by vertex
//     (draco_quantised_positions, meshopt_quantised_positions) and the largest distance taken.
//  3. encode, decode, and check that the decoded triangles are the welded triangles with every corner
//     at its replayed position (as sets of oriented triangles by corner positions; Draco reorders).
//     Then the bound holds: a point of a decoded triangle is the same barycentric combination of its
//     displaced corners, so it moved no more than the largest displacement; every mesh point stays
//     within c + displacement <= D of the surfaces and every surface point within that of the mesh.
// One tessellation per f serves every codec asked for. The smallest result over f is kept (Draco: raw
// bytes, Draco being entropy coded already; meshopt: gzip'd bytes, the figure gltfpack users compare),
// then its decoded mesh is measured against the NURBS with measure_deviation (two-sided, by sampling:
// a check of the bound, not the bound).
#include <string>
#include <vector>

#include "analysis/measure/measure_deviation.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/scene.hpp"

namespace cadnurbs {

enum class MeshCodec { draco, meshopt };

// "draco" or "meshopt".
const char* mesh_codec_name(MeshCodec codec);

struct MeshEncodingOptions {
  std::vector<double> fractions = {0.5, 0.7, 0.85};  // f, each in (0, 1)
  int draco_speed = 0;                               // Draco's speed option, 0 = best compression
  DeviationOptions measure = {};                     // sampling of the measurement after decoding
  bool measure_after_decoding = true;                // false: the bound alone (`measured` stays empty)
};

struct MeshEncodingFigures {
  MeshCodec codec = MeshCodec::draco;
  double max_deviation = 0;          // D asked for
  std::string bytes;                 // the encoded mesh as the codec writes it
  long raw_bytes = 0;                // bytes.size()
  long gzip_bytes = 0;               // gzip (level 9) of bytes
  int position_bits = 0;             // quantisation bits per axis
  double fraction = 0;               // f: the tessellation was made at f * D
  double certified_deviation = 0;    // c: the tessellation's certified bound (<= f * D)
  double displacement_budget = 0;    // D - c: what quantisation may move a vertex
  double displacement = 0;           // largest vertex displacement by quantisation (exact)
  double deviation_bound = 0;        // c + displacement <= D
  DeviationMeasure measured;         // the decoded mesh against the NURBS, two-sided (if asked for)
  long vertices = 0, triangles = 0;  // of the decoded mesh
  TriangleMesh certified_mesh;       // the welded tessellation that was quantised (world coordinates)
};

// The smallest encoding of `scene` with each of `codecs` (same order) within `max_deviation` (method
// above). Only trimmed NURBS surfaces are encoded (curves are ignored). Throws GeometryError (entity
// "mesh encoding") for max_deviation <= 0 or fractions outside (0, 1), a scene with mesh or polygon
// shapes (nothing exact to measure them against) or without surfaces, a tessellation with uncertified
// triangles, no bits up to 30 within the budget (once hair-apart corners are welded, see
// with_hair_apart_corners_welded), or a decoded mesh that is not the quantised input;
// passes on the tessellator's and codecs' errors.
std::vector<MeshEncodingFigures> encode_mesh_within(const Scene& scene, double max_deviation,
                                                    const std::vector<MeshCodec>& codecs,
                                                    const MeshEncodingOptions& options = {});
// The same for one codec.
MeshEncodingFigures encode_mesh_within(const Scene& scene, double max_deviation, MeshCodec codec,
                                       const MeshEncodingOptions& options = {});

// Step 1 of the method: the scene's surfaces tessellated within `deviation` in world coordinates, as one
// mesh welded by exact position. `report` (optional) gets the tessellation's figures.
TriangleMesh certified_world_mesh(const Scene& scene, double deviation, TessellationReport* report = nullptr);

// The coarsest bits (1..30) at which `codec` moves no vertex of `mesh` farther than `budget` and puts no
// two corners of a triangle on one grid point (a collapsed triangle is dropped by Draco, and a thin
// feature that collapses whole is then lost), with that largest displacement; bits 0 when none does.
struct QuantisationChoice {
  int bits = 0;
  double displacement = 0;
};
QuantisationChoice coarsest_quantisation(const TriangleMesh& mesh, MeshCodec codec, double budget);

// `mesh` made quantisable when corners a hair apart (a trimming loop that passes a point twice, a seam
// computed two ways: 1e-14 mm apart in KiCad parts) leave a triangle that collapses at every bit count:
// then it is welded (weld_vertices) within a hundredth of `budget`, and `moved` gets the largest merge,
// which bounds how far any triangle moved (a triangle that collapses lies along the edge its neighbour
// keeps). Otherwise `mesh` comes back unchanged and `moved` is 0.
TriangleMesh with_hair_apart_corners_welded(const TriangleMesh& mesh, MeshCodec codec, double budget, double* moved);

// Largest distance a vertex of `mesh` moves under `codec`'s quantisation at `bits`.
double quantisation_displacement(const TriangleMesh& mesh, MeshCodec codec, int bits);

}  // namespace cadnurbs
