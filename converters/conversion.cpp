#include "converters/conversion.hpp"

#include <filesystem>

#include "analysis/tessellation/tessellate_uniform.hpp"
#include "converters/arguments.hpp"
#include "converters/cnb_coding.hpp"
#include "core/bounding_box.hpp"
#include "core/geometry_error.hpp"
#include "core/number_format.hpp"
#include "core/world_scale.hpp"
#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"
#include "formats/vrml/scene_graph_rewrite.hpp"
#include "formats/vrml/viewpoint.hpp"

namespace cadnurbs {

namespace {

constexpr double kSubdShareOfDeviation = 0.1;

// The share of D a quantising format's mesh is tessellated to (the rest is the quantisation's).
constexpr double kTessellationShare = 0.7;

// A NURBS format that quantises (.cnb, .html): --deviation is its bound, not a request for a mesh.
bool quantises_nurbs(const FileFormat& format) { return format.quantises && !format.meshes_only; }

// Takes the NURBS curves out of `node` and its children (a format that holds triangles only has no place
// for them); returns how many.
int drop_curves(SceneNode& node) {
  const auto before = node.shapes.size();
  std::erase_if(node.shapes, [](const Shape& shape) { return std::holds_alternative<NurbsCurve>(shape.geometry); });
  int dropped = static_cast<int>(before - node.shapes.size());
  for (auto& child : node.children) dropped += drop_curves(child);
  return dropped;
}

bool holds_geometry(const SceneCounts& c) {
  return c.surfaces + c.trimmed_surfaces + c.curves + c.meshes + c.polygon_meshes > 0;
}

// A file without geometry is never written: the conversion fails, naming what the input held and why
// none of it is there (the reader's first note or repair line, and how many more it gave).
void refuse_empty(const std::string& input, const BrepTranslation& loaded, const std::string& what) {
  std::vector<std::string> lines = loaded.notes;
  lines.insert(lines.end(), loaded.repairs.begin(), loaded.repairs.end());
  std::string why = lines.empty() ? "the file holds none that cadnurbs reads" : lines.front();
  if (lines.size() > 1) why += "; " + std::to_string(lines.size() - 1) + " more such line" + (lines.size() > 2 ? "s" : "");
  throw FileError(input + ": " + what + " (" + why + ")");
}

template <class Function, class... Args>
void tell(const Function& listener, const Args&... args) {
  if (listener) listener(args...);
}

}  // namespace

bool writes_mesh(const ConversionRequest& request, const FileFormat& output) {
  return request.mesh || request.steps > 0 || (request.deviation > 0 && !quantises_nurbs(output)) ||
         output.meshes_only;
}

void check_request(const ConversionRequest& request) {
  const FileFormat& output = output_format(request.output);
  if (request.compression && file_extension(request.output) != ".glb")
    throw UsageError("--compress applies to .glb output only");
  if (request.simplify > 0 && writes_mesh(request, output)) throw UsageError("--simplify applies to NURBS output only");
}

bool keeps_scene_graph(const ConversionRequest& request) {
  const FileFormat& in = request.input_format ? *request.input_format : input_format(request.input);
  const FileFormat& out = output_format(request.output);
  return vrml_text_form(in) && vrml_text_form(out) && !request.mesh && request.steps == 0 && request.deviation == 0 &&
         request.simplify == 0 && !request.unit && request.precision == 0;
}

namespace {

// The input file's scene graph in the output's encoding; the Scene read from it only counts.
ConversionResult write_scene_graph(const ConversionRequest& request, const Scene& scene, const ConversionLog& log) {
  const VrmlTextForm form = *vrml_text_form(output_format(request.output));
  VrmlWriteOptions options;
  options.encoding = form.encoding;
  options.self_contained = request.self_contained;
  options.pretty = request.pretty;
  const RewrittenSceneGraph graph = rewrite_scene_graph(read_file(request.input), request.input, options);
  write_file_atomically(request.output, form.gzipped ? gzip(graph.text) : graph.text);
  if (form.encoding == VrmlEncoding::vrml97 && !options.self_contained)
    write_nurbs_protos_beside(request.output, options.protos_url);
  ConversionResult result;
  result.counts = count_entities(scene);
  result.scene_graph = ConversionResult::SceneGraph{graph.nodes, graph.kinds, graph.routes, graph.protos, graph.notes};
  result.deviation_bound = 0;
  result.deviation_basis = "bound: the numbers are written as read";
  tell(log.written, scene, result);
  return result;
}

}  // namespace

LoadedInput load_input(const ConversionRequest& request) {
  const FileFormat& format = request.input_format ? *request.input_format : input_format(request.input);
  LoadedInput input;
  SceneReadOptions read = request.read;
  // A SubD's fitted patches take a tenth of the deviation asked for (given in the output's unit; the
  // reader works in millimetres), so that the mesh made of them stays near D of the limit surface.
  if (request.deviation > 0 && read.subd_deviation == 0)
    read.subd_deviation = kSubdShareOfDeviation * request.deviation * (request.unit ? request.unit->millimetres : 1.0);
  input.loaded = load_scene_as(request.input, format, read);
  input.scene = request.unit ? in_unit(input.loaded.scene, *request.unit) : input.loaded.scene;
  return input;
}

SceneWriteOptions scene_write_options(const ConversionRequest& request, const Scene& scene, double diagonal) {
  SceneWriteOptions options;
  options.homogeneous_control_points = request.read.homogeneous_control_points;
  options.significant_digits = request.precision;
  options.self_contained = request.self_contained;
  options.pretty = request.pretty;
  options.title = std::filesystem::path(request.input).filename().string();
  if (request.compression) options.compression = *request.compression;
  options.viewpoint = framing_viewpoint(scene_bounding_box(scene));
  options.display_deviation = request.display_deviation >= 0 ? request.display_deviation : 1e-3 * diagonal;
  if (quantises_nurbs(output_format(request.output)))
    options.quantisation_budget =
        request.deviation > 0 ? request.deviation : default_deviation(diagonal, request.input);
  return options;
}

namespace {

ConversionResult convert_scene(const ConversionRequest& request, const LoadedInput& input, const ConversionLog& log) {
  const FileFormat& format = output_format(request.output);
  const Scene& scene = input.scene;
  if (!holds_geometry(count_entities(scene))) refuse_empty(request.input, input.loaded, "no geometry to write");
  const double diagonal = checked_diagonal(scene, request.input);
  if (keeps_scene_graph(request)) return write_scene_graph(request, scene, log);
  const bool mesh = writes_mesh(request, format);
  const double tolerance = written_tolerance(scene, request.precision);
  std::optional<Scene> simplified;
  double simplified_by = 0;  // the simplification's certified deviation
  if (request.simplify > 0) {
    SimplifiedScene s = simplified_scene(scene, request.simplify, tolerance);
    tell(log.simplified, s);
    if (s.certified_deviation > request.simplify)
      throw FileError(request.input + ": --simplify " + number_text(request.simplify, 4) +
                      ": the certified deviation " + number_text(s.certified_deviation, 4) + " exceeds it");
    simplified_by = s.certified_deviation;
    simplified = std::move(s.scene);
  }
  const Scene& source = simplified ? *simplified : scene;
  SceneWriteOptions options = scene_write_options(request, scene, diagonal);
  ConversionResult result;
  Scene written;
  if (mesh && request.steps > 0) {
    written = tessellate_uniform(scene, request.steps);
    result.steps = request.steps;
    result.deviation_basis = "uniform tessellation: no bound";
  } else if (mesh) {
    ConversionResult::Mesh m;
    m.deviation = request.deviation > 0 ? request.deviation : default_deviation(diagonal, request.input);
    m.check_areas = request.check_areas;
    // A quantising writer gets its share of D: the mesh at 0.7 D, vertices moved by at most 0.3 D.
    m.quantised = format.quantises;
    m.tessellated = format.quantises ? kTessellationShare * m.deviation : m.deviation;
    if (format.quantises) options.quantisation_budget = m.deviation - m.tessellated;
    m.quantisation_budget = options.quantisation_budget;
    CertifiedMesh meshed = certified_mesh(input.loaded, scene, m.tessellated, request.check_areas);
    if (meshed.sewn) tell(log.sewn, meshed);
    m.report = meshed.report;
    written = std::move(meshed.meshes);
    result.mesh = m;
    // The certificate holds in each face's own coordinates; a placement that stretches stretches it.
    const double stretch = largest_world_scale(written);
    if (m.report.uncertified_triangles > 0) {
      result.deviation_basis = "no bound: " + std::to_string(m.report.uncertified_triangles) +
                               " triangles are not certified";
    } else {
      result.deviation_bound = stretch * m.report.certified_deviation + m.quantisation_budget;
      result.deviation_basis = "bound: the tessellator's certificate";
      if (stretch > 1 + 1e-9) result.deviation_basis += " times the placement's largest stretch";
      if (m.quantised) result.deviation_basis += " plus the quantisation budget";
    }
  } else if (format.compact && !request.exact_nurbs) {
    CompactReport report;
    written = compact_scene(source, tolerance, &report);
    tell(log.compacted, report);
    result.deviation_bound = simplified_by + tolerance + options.quantisation_budget;
    result.deviation_basis = "bound: nothing moved by more than the written precision";
  } else {
    written = source;
    if (format.compact) {  // the text writers round to the written precision
      result.deviation_bound = simplified_by + 0.5 * tolerance + options.quantisation_budget;
      result.deviation_basis = "bound: half the written precision (rounding)";
    }
  }
  if (simplified) result.deviation_basis += ", after the simplification's certificate";
  if (!mesh && options.quantisation_budget > 0) result.deviation_basis += " plus the quantisation budget";
  if (format.meshes_only) {
    const int curves = drop_curves(written.root);
    if (curves > 0) tell(log.curves_dropped, curves);
    if (!holds_geometry(count_entities(written)))
      throw FileError(request.input + ": no geometry to write: its " + std::to_string(curves) +
                      " curves have no place in " + file_extension(request.output));
  }
  if (quantises_nurbs(format) && !mesh) {  // .cnb, .html: write_as_cnb's coding, with its report for the log
    const bool compacted = format.compact && !request.exact_nurbs;
    CnbCoding coding =
        cnb_coding(written, options.quantisation_budget, compacted ? &source : nullptr, !request.exact_nurbs);
    tell(log.coded, coding);
    result.deviation_basis += meshed_bodies_basis(coding.choice);
    format.write_coded(request.output, coding.bytes);
    written = std::move(coding.scene);
  } else {
    write_scene(request.output, written, options);
  }
  result.counts = count_entities(written);
  tell(log.written, written, result);
  return result;
}

}  // namespace

// Geometry the reader accepted can still fail later (a face the tessellator cannot mesh): the error then
// names the face but not the file, which the user needs when a batch converts hundreds.
ConversionResult convert_loaded(const ConversionRequest& request, const LoadedInput& input, const ConversionLog& log) {
  try {
    return convert_scene(request, input, log);
  } catch (const GeometryError& error) {
    throw FileError(request.input + ": " + error.what());
  }
}

ConversionResult convert_file(const ConversionRequest& request, const ConversionLog& log) {
  const LoadedInput input = load_input(request);
  tell(log.loaded, input.loaded);
  return convert_loaded(request, input, log);
}

}  // namespace cadnurbs
