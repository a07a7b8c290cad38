#pragma once
// What the report knows about one part: the thesis's float counts and, for every representation, the
// bytes of a file actually written and read back, with its deviation from the part (a bound wherever one
// exists, else measured face by face) and which of the two it is.
// One record per part; report_markdown / report_json / report_csv lay records out (schema: docs/report.md).
#include <limits>
#include <string>
#include <vector>

#include "report/storage_accounting.hpp"

namespace cadnurbs {

// nurss: a subdivision surface's control mesh (its bytes against the NURBS's and the meshes'); loop: a
// Loop subdivision control mesh fitted to a mesh input (against the meshes users have).
enum class RepresentationKind { nurbs, mesh, nurss, loop };

// How a deviation figure is known. bound: it cannot be exceeded (the tessellator's certificate, a
// written precision, a quantisation replayed vertex by vertex, a codec's proven bound). measured: an
// attained value from sampling, face by face (the truth may exceed it between samples).
enum class DeviationKind { bound, measured };

// "bound" or "measured", as the JSON, CSV and pages say it.
const char* deviation_kind_name(DeviationKind kind);

// One written file.
struct RepresentationFigures {
  std::string key;    // stable identifier: "x3dv-compact", "wrl-mesh", "draco", ...
  std::string label;  // for people: "X3D classic NURBS, compact"
  RepresentationKind kind = RepresentationKind::nurbs;
  long bytes = 0;       // the file as written
  long gzip_bytes = 0;  // that file gzip'd at level 9 (for a file that is already compressed: the same)
  long floats = 0;      // thesis accounting of what the file holds (storage_accounting.hpp)
  long integers = 0;    // indices, polygon corners, connectivity
  // Largest distance between what reading the file back gives and the exact surfaces of the part (for a
  // mesh input: the input mesh), a bound wherever one exists, else measured face by face after reading
  // it back; NaN where it is not known.
  double deviation = std::numeric_limits<double>::quiet_NaN();
  std::string deviation_basis;  // how `deviation` was obtained, for people
  DeviationKind deviation_kind = DeviationKind::measured;
};

// Bytes of one representation at one maximum deviation (the storage-against-accuracy curve).
struct StoragePoint {
  std::string key;
  double deviation = 0;  // the D asked for
  long bytes = 0, gzip_bytes = 0, floats = 0;  // the certified mesh at `deviation` (not measured again)
};

// Where a mesh encoding's curve crosses the NURBS's bytes (report/storage_crossover.hpp).
struct CrossoverFigure {
  std::string mesh_key;    // the curve's key
  std::string nurbs_key;   // the NURBS file compared (the smallest delivered one)
  long nurbs_bytes = 0;    // its delivered bytes (the smaller of raw and gzip'd)
  double deviation = std::numeric_limits<double>::quiet_NaN();  // below it the mesh costs more; NaN: no crossing
  bool mesh_larger_everywhere = false;  // no crossing because the mesh cost more at every measured D
};

struct PartRecord {
  std::string input;            // the path as given
  bool failed = false;
  std::string error;            // the one-line reason when failed
  std::string unit;             // of every length below
  double diagonal = 0;          // of the part's bounding box
  double deviation = 0;         // D: the maximum deviation every mesh figure is made at
  NurbsStorage nurbs;           // the source NURBS, exact (as --exact-nurbs writes them)
  NurbsStorage compact_nurbs;   // after the compact writer's rewrites
  MeshStorage mesh;             // the certified mesh at D, welded
  double mesh_certified_deviation = 0;  // the tessellator's bound for that mesh
  std::vector<RepresentationFigures> representations;
  std::vector<StoragePoint> curve;       // empty unless asked for
  std::vector<CrossoverFigure> crossovers;  // one per mesh key of the curve
  std::vector<std::string> warnings;     // repairs and fallbacks the reader reported
};

// The representation `key` of `record`, or null.
const RepresentationFigures* find_representation(const PartRecord& record, const std::string& key);

// What delivering a representation costs: the smaller of the file and its gzip'd form.
inline long delivered_bytes(const RepresentationFigures& r) { return r.bytes < r.gzip_bytes ? r.bytes : r.gzip_bytes; }

// The kind's name in the report's JSON and the HTML pages' data: "nurbs", "mesh", "nurss", "loop".
const char* representation_kind_name(RepresentationKind kind);

// The representation of `kind` with the fewest delivered bytes (the first of equals), or null.
const RepresentationFigures* smallest_representation(const PartRecord& record, RepresentationKind kind);

}  // namespace cadnurbs
