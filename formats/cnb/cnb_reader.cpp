#include "formats/cnb/cnb_reader.hpp"

#include <cmath>
#include <limits>

#include "core/geometry_error.hpp"
#include "formats/cnb/cnb_colours.hpp"
#include "formats/cnb/cnb_container.hpp"
#include "formats/cnb/cnb_geometry.hpp"
#include "formats/cnb/cnb_scene_layout.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

using namespace cnb;

// A trimmed surface record: the net, the trim grid's exponent, the loops.
Geometry read_trimmed_surface(ByteReader& in, double q, CodingState& state) {
  TrimmedSurface t;
  t.surface = read_surface(in, q, state);
  const size_t e_at = in.offset();
  const int64_t e = in.varsint(Field::structure);
  if (e < -100 || e > 100) in.fail("trim grid exponent " + std::to_string(e) + " outside -100..100", e_at);
  t.loops = read_trim_loops(in, static_cast<int>(e), state);
  return t;
}

struct SceneDecoder {
  ByteReader& in;
  double q = 0;
  CodingState state;

  // Refuses a scene whose numbers exceed the budget the payload's size allows.
  void count_numbers(const Geometry& g, size_t at) {
    size_t n = 0;
    if (const auto* t = std::get_if<TrimmedSurface>(&g)) {
      n = 4 * t->surface.points.size() + t->surface.u_knots.size() + t->surface.v_knots.size();
      for (const auto& loop : t->loops)
        for (const auto& segment : loop.segments)
          n += std::holds_alternative<NurbsCurve>(segment) ? 4 * std::get<NurbsCurve>(segment).points.size()
                                                           : 2 * std::get<Polyline2D>(segment).points.size();
    } else if (const auto* c = std::get_if<NurbsCurve>(&g)) {
      n = 4 * c->points.size() + c->knots.size();
    } else if (const auto* m = std::get_if<TriangleMesh>(&g)) {
      n = 3 * m->positions.size() + 3 * m->triangles.size() + 3 * m->corner_normals.size();
    } else {
      const auto& p = std::get<PolygonMesh>(g);
      n = 3 * p.positions.size() + p.polygons.size();
      for (const auto& polygon : p.polygons) n += polygon.size();
    }
    numbers += n;
    if (numbers > number_budget)
      in.fail("the scene would hold more than " + std::to_string(number_budget) + " numbers (" +
                  std::to_string(numbers_per_payload_byte) + " per payload byte and " +
                  std::to_string(numbers_allowance) + ")",
              at);
  }

  Colour colour() { return read_colour(in, colours, state.version); }

  double finite_float(const char* what) {
    const size_t at = in.offset();
    const double v = in.float64();
    if (!std::isfinite(v)) in.fail(std::string(what) + " is not finite", at);
    return v;
  }

  // The geometry of each shape kind but the repeat (cnb_scene_layout.hpp), by kind.
  using GeometryReader = Geometry (*)(ByteReader&, double, CodingState&);
  static constexpr GeometryReader geometry_readers[] = {
      read_trimmed_surface,
      [](ByteReader& in, double q, CodingState& state) -> Geometry { return read_curve(in, q, state); },
      [](ByteReader& in, double q, CodingState&) -> Geometry { return read_triangle_mesh(in, q); },
      [](ByteReader& in, double q, CodingState&) -> Geometry { return read_polygon_mesh(in, q); },
      nullptr,  // repeated_shape_kind: handled before
      [](ByteReader& in, double q, CodingState& state) -> Geometry { return read_traversal_mesh(in, q, state); },
  };

  std::vector<Geometry> geometries;  // of every shape so far, for repeated ones
  size_t numbers = 0, number_budget = 0;

  // Validates a decoded shape's geometry, counts its numbers and keeps it for repeats.
  void accept(const Shape& s, const std::string& path, size_t start) {
    const std::string entity =
        path + "/" + (s.name.empty() ? "shape at decoded byte " + std::to_string(start) : s.name);
    try {
      // Loops keep whatever closure they had when written; their closure is not this reader's to judge.
      if (const auto* t = std::get_if<TrimmedSurface>(&s.geometry))
        validate(*t, entity, std::numeric_limits<double>::infinity());
      else
        std::visit([&](const auto& g) { validate(g, entity); }, s.geometry);
    } catch (const GeometryError& e) {
      in.fail(std::string("invalid shape: ") + e.what(), start);
    }
    count_numbers(s.geometry, start);
    geometries.push_back(s.geometry);
  }

  // A mesh group's shapes (at most `room` of them: the node's shapes not yet read).
  std::vector<Shape> mesh_group(const std::string& path, size_t start, size_t room, bool with_copies) {
    const size_t count_at = in.offset();
    const size_t count = in.count(3);
    const size_t fewest = with_copies ? 1 : 2;  // one mesh is a group only for its copies
    if (count < fewest || count > static_cast<size_t>(max_group_meshes) || count > room)
      in.fail("a mesh group of " + std::to_string(count) + " shapes (" + std::to_string(fewest) + " to " +
                  std::to_string(max_group_meshes) + ", and " + std::to_string(room) + " left in the node)",
              count_at);
    std::vector<Shape> shapes(count);
    for (auto& s : shapes) {
      const size_t flags_at = in.offset();
      const uint8_t flags = in.byte(Field::structure);
      if (flags & ~has_colour_flag) in.fail("unknown mesh group flags " + std::to_string(flags), flags_at);
      s.name = in.text();
      if (flags & has_colour_flag) s.colour = colour();
    }
    std::vector<TriangleMesh> meshes =
        read_mesh_group(in, static_cast<int>(count), q, state, with_copies, number_budget - numbers);
    for (size_t i = 0; i < count; ++i) {
      shapes[i].geometry = std::move(meshes[i]);
      accept(shapes[i], path, start);
    }
    return shapes;
  }

  // The next record's shapes: one, or a mesh group's (at most `room`).
  std::vector<Shape> shapes(const std::string& path, size_t room) {
    const size_t start = in.offset();
    const uint8_t kind_byte = in.byte(Field::structure);
    if (kind_byte == mesh_group_kind || (kind_byte == mesh_group_with_copies_kind && state.version >= 5))
      return mesh_group(path, start, room, kind_byte == mesh_group_with_copies_kind);
    const uint8_t kind = kind_byte & ~has_colour_flag;
    if (kind > traversal_mesh_kind) in.fail("unknown shape kind " + std::to_string(kind_byte), start);
    Shape s;
    s.name = in.text();
    if (kind_byte & has_colour_flag) s.colour = colour();
    if (kind == repeated_shape_kind) {
      const size_t at = in.offset();
      const uint64_t back = in.varuint(Field::index);
      if (back >= geometries.size())
        in.fail("a repeat of shape " + std::to_string(back + 1) + " back, with " + std::to_string(geometries.size()) +
                    " before it",
                at);
      s.geometry = geometries[geometries.size() - 1 - back];
      count_numbers(s.geometry, at);
      geometries.push_back(s.geometry);
      return {std::move(s)};
    }
    s.geometry = geometry_readers[kind](in, q, state);
    accept(s, path, start);
    return {std::move(s)};
  }

  SceneNode node(const std::string& parent_path, int depth) {
    if (depth > deepest_node) in.fail("nodes nested deeper than " + std::to_string(deepest_node));
    SceneNode n;
    n.name = in.text();
    const std::string path = parent_path.empty() ? (n.name.empty() ? "scene" : n.name) : parent_path + "/" + n.name;
    const size_t flags_at = in.offset();
    const uint8_t flags = in.byte(Field::structure);
    if (flags & ~(node_colour_flag | node_linear_flag | node_translation_flag | node_exact_numbers_flag))
      in.fail("unknown node flags " + std::to_string(flags), flags_at);
    const bool exact_numbers = flags & node_exact_numbers_flag;
    auto number = [&](const char* what) { return exact_numbers ? read_exact_number(in) : finite_float(what); };
    if (flags & node_colour_flag) n.colour = colour();
    if (flags & node_linear_flag) {
      const size_t at = in.offset();
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) n.transform.linear()(r, c) = number("a transform entry");
      if (!(std::abs(n.transform.linear().determinant()) > 0)) in.fail("a singular transform", at);
    }
    if (flags & node_translation_flag)
      for (int k = 0; k < 3; ++k) n.transform.translation()(k) = number("a translation");
    const size_t shape_count = in.count(2);
    n.shapes.reserve(shape_count);
    while (n.shapes.size() < shape_count)
      for (Shape& s : shapes(path, shape_count - n.shapes.size())) n.shapes.push_back(std::move(s));
    const size_t child_count = in.count(3);
    n.children.reserve(child_count);
    for (size_t i = 0; i < child_count; ++i) n.children.push_back(node(path, depth + 1));
    return n;
  }

  ColourCache colours;  // met so far in the file (version 4)
};

// A payload source that also keeps each byte and the context it was read in.
class RecordingSource : public ByteSource {
 public:
  RecordingSource(ByteSource& source, CnbPayload& record) : source_(source), record_(record) {}
  uint8_t next(int context) override {
    const uint8_t b = source_.next(context);
    record_.bytes.push_back(static_cast<char>(b));
    record_.contexts.push_back(static_cast<uint8_t>(context));
    return b;
  }

 private:
  ByteSource& source_;
  CnbPayload& record_;
};

Scene decode_scene(ByteSource& source, const OpenedPayload& payload, const std::string& name, CnbFileFacts* facts = nullptr) {
  ByteReader in(source, payload.size);
  try {
    Scene scene;
    SceneDecoder decoder{in, 0, {}, {}, 0, numbers_per_payload_byte * payload.size + numbers_allowance, {}};
    decoder.state.version = payload.version;
    // Version 1 wrote the units' sizes and D as raw float64, versions 2 and 3 as exact numbers; versions 1
    // and 2 wrote q and the bound as raw float64, version 3 q as a float32 and the bound as an exact number.
    auto number = [&](const char* what) {
      return payload.version == 1 ? decoder.finite_float(what) : read_exact_number(in);
    };
    scene.unit.name = in.text();
    scene.unit.millimetres = number("the unit's size");
    scene.source_unit.name = in.text();
    scene.source_unit.millimetres = number("the source unit's size");
    const double asked = number("the maximum deviation");
    const size_t q_at = in.offset();
    decoder.q = payload.version < 3 ? in.float64() : static_cast<double>(in.float32());
    if (!(decoder.q > 0) || !std::isfinite(decoder.q)) in.fail("the grid step is not positive and finite", q_at);
    const double bound = payload.version < 3 ? decoder.finite_float("the deviation bound") : read_exact_number(in);
    if (facts) *facts = {asked, bound};
    scene.root = decoder.node("", 0);
    if (in.left() > 0) in.fail(std::to_string(in.left()) + " bytes after the scene");
    return scene;
  } catch (const PayloadError& e) {
    throw FileError(name + ": decoded byte " + std::to_string(e.offset) + ": " + e.what());
  }
}

}  // namespace

Scene read_cnb(const std::string& bytes, const std::string& name, CnbFileFacts* facts) {
  const OpenedPayload payload = open_payload(bytes, name);
  return decode_scene(*payload.source, payload, name, facts);
}

CnbPayload read_cnb_payload(const std::string& bytes, const std::string& name) {
  const OpenedPayload payload = open_payload(bytes, name);
  CnbPayload record;
  record.version = payload.version;
  record.arithmetic = payload.arithmetic;
  RecordingSource source(*payload.source, record);
  decode_scene(source, payload, name);
  return record;
}

}  // namespace cadnurbs
