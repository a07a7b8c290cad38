#pragma once
// One conversion, the one place where a scene is read, made ready for an output format and written with
// its writer's options: `convert` runs it, `batch` runs it for each output of a part, and `report` builds
// the files it measures with its write options (scene_write_options) so that it measures what convert
// writes. The commands only fill a ConversionRequest and print what the steps report (ConversionLog).
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "analysis/coding_choice/cheapest_coding.hpp"
#include "converters/cnb_coding.hpp"
#include "converters/file_formats.hpp"
#include "converters/scene_preparation.hpp"
#include "core/length_unit.hpp"

namespace cadnurbs {

// What a conversion is asked for: convert's options, as values.
struct ConversionRequest {
  std::string input, output;
  const FileFormat* input_format = nullptr;  // --from; null: the format the input's name says
  SceneReadOptions read;                     // --euclidean, the STEP/IGES wall and its limits
  std::optional<LengthUnit> unit;            // --units; none: millimetres, as read
  bool mesh = false;                         // --mesh
  int steps = 0;                             // --steps N: uniform tessellation (a mesh); 0: not asked
  double deviation = 0;                      // --deviation D; 0: not given (1e-3 of the bounding-box diagonal)
  double display_deviation = -1;             // --display-deviation D; < 0: not given (1e-3 of the diagonal)
  double simplify = 0;                       // --simplify D; 0: not asked
  bool check_areas = false;                  // --check-areas
  bool exact_nurbs = false;                  // --exact-nurbs
  int precision = 0;                         // --precision N; 0: automatic
  bool pretty = false;                       // --pretty
  bool self_contained = false;               // --self-contained
  std::optional<std::string> compression;    // --compress C; none: the writer's default
};

// Whether the request writes a mesh: --mesh, --steps, --deviation for a format that does not quantise
// NURBS (for .cnb it is the bound of its quantisation), or a format that holds triangles only.
bool writes_mesh(const ConversionRequest& request, const FileFormat& output);

// The request's option combinations that do not fit its output, refused before any work (UsageError):
// "--compress applies to .glb output only", "--simplify applies to NURBS output only".
void check_request(const ConversionRequest& request);

// The input read as the request says, and in the request's unit.
struct LoadedInput {
  BrepTranslation loaded;  // as read (millimetres), with its repairs and fallbacks
  Scene scene;             // in the request's unit
};
LoadedInput load_input(const ConversionRequest& request);

// The writer's options for writing the conversion of `scene` (the input in the request's unit, whose
// checked_diagonal is `diagonal`) as the request says: its precision, control-point convention, PROTOs,
// layout, title (the input's file name), the Viewpoint framing the input's bounding box (the mesh and the
// NURBS file of a part render from the same place), the display deviation of the tessellation hints (1e-3
// of the diagonal unless given) and, for .cnb, the quantisation budget (the deviation, 1e-3 of the
// diagonal unless given). A certified mesh for a quantising format gets its own budget (convert_loaded).
SceneWriteOptions scene_write_options(const ConversionRequest& request, const Scene& scene, double diagonal);

struct ConversionResult;

// What the steps tell as they end, for the command to print (each may be empty: batch prints nothing).
struct ConversionLog {
  std::function<void(const BrepTranslation&)> loaded;       // repairs and fallen-back faces
  std::function<void(const SimplifiedScene&)> simplified;   // --simplify: before its certificate is judged
  std::function<void(const CertifiedMesh&)> sewn;           // a mesh of a file that named no edges
  std::function<void(const CompactReport&)> compacted;      // compact NURBS output
  std::function<void(int curves)> curves_dropped;           // NURBS curves a triangles-only format cannot hold
  std::function<void(const CnbCoding&)> coded;              // .cnb: the bodies written as certified meshes
  // Once written: the scene as handed to the writer, and what the conversion returns.
  std::function<void(const Scene&, const ConversionResult&)> written;
};

// What was written.
struct ConversionResult {
  SceneCounts counts;  // of the written scene
  int steps = 0;       // the uniform tessellation's steps per span, when it was one
  // The certified mesh's figures, when it was one.
  struct Mesh {
    double deviation = 0;            // D asked for
    double tessellated = 0;          // what the tessellator was asked for (D, or 0.7 D for a quantising format)
    double quantisation_budget = 0;  // what the writer may move a vertex by (D - tessellated)
    bool quantised = false;
    bool check_areas = false;
    TessellationReport report;
  };
  std::optional<Mesh> mesh;
  // The input's whole VRML/X3D scene graph, when it was kept (keeps_scene_graph).
  struct SceneGraph {
    size_t nodes = 0, kinds = 0, routes = 0, protos = 0;
    std::vector<std::string> notes;  // what the translation between VRML97 and X3D dropped or declared
  };
  std::optional<SceneGraph> scene_graph;
  // How far the written file can be from the input's surfaces, a bound, and how it is known: the
  // tessellator's certificate (plus the quantisation budget), the compact rewrites' and the written
  // precision's, the simplification's certificate. NaN where no bound is known (--steps, STEP/IGES out).
  double deviation_bound = std::numeric_limits<double>::quiet_NaN();
  std::string deviation_basis;
};

// Whether the conversion writes the input's whole scene graph again (scene_graph_rewrite.hpp) rather
// than the Scene: input and output are both VRML/X3D and nothing asked changes geometry (no --mesh,
// --steps, --deviation, --simplify, --units or --precision).
bool keeps_scene_graph(const ConversionRequest& request);

// Converts `input` (load_input of the same request) to request.output: the certified mesh, the uniform
// tessellation, the simplified, compact or exact NURBS, as the request and the output format say, written
// with scene_write_options. Throws FileError "<input>: --simplify D: the certified deviation X exceeds it"
// and the readers' and writers' one-line errors.
ConversionResult convert_loaded(const ConversionRequest& request, const LoadedInput& input,
                                const ConversionLog& log = {});

// load_input, then convert_loaded (log.loaded told between them).
ConversionResult convert_file(const ConversionRequest& request, const ConversionLog& log = {});

}  // namespace cadnurbs
