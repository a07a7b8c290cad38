// formats/scene_stream: a scene (and a B-rep reader's whole result) read back from its stream is the same
// to the bit in every field, and a stream that write_*_stream did not make is refused with one line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "formats/common/file_io.hpp"
#include "formats/scene_stream/scene_stream.hpp"
#include "formats/step/step_reader.hpp"
#include "samples/capping.hpp"
#include "samples/capping_shapes.hpp"

namespace cadnurbs {
namespace {

// Field-by-field comparison; doubles by their bits (NaN, -0.0 included). Counts the doubles compared.
struct Same {
  long doubles = 0;
  void number(double a, double b, const std::string& where) {
    ++doubles;
    EXPECT_EQ(0, std::memcmp(&a, &b, sizeof a)) << where << ": " << a << " vs " << b;
  }
  void numbers(const std::vector<double>& a, const std::vector<double>& b, const std::string& where) {
    ASSERT_EQ(a.size(), b.size()) << where;
    for (size_t i = 0; i < a.size(); ++i) number(a[i], b[i], where);
  }
  void points(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b, const std::string& where) {
    ASSERT_EQ(a.size(), b.size()) << where;
    for (size_t i = 0; i < a.size(); ++i) for (int k = 0; k < 3; ++k) number(a[i][k], b[i][k], where);
  }
  void colour(const std::optional<Colour>& a, const std::optional<Colour>& b, const std::string& where) {
    ASSERT_EQ(a.has_value(), b.has_value()) << where;
    if (a) {
      number(a->r, b->r, where);
      number(a->g, b->g, where);
      number(a->b, b->b, where);
    }
  }
  void curve(const NurbsCurve& a, const NurbsCurve& b, const std::string& where) {
    EXPECT_EQ(a.dimension, b.dimension) << where;
    EXPECT_EQ(a.order, b.order) << where;
    numbers(a.knots, b.knots, where);
    points(a.points, b.points, where);
    numbers(a.weights, b.weights, where);
  }
  void geometry(const Geometry& a, const Geometry& b, const std::string& where) {
    ASSERT_EQ(a.index(), b.index()) << where;
    if (const auto* t = std::get_if<TrimmedSurface>(&a)) {
      const auto& u = std::get<TrimmedSurface>(b);
      const NurbsSurface &s = t->surface, &r = u.surface;
      EXPECT_EQ(std::tie(s.u_order, s.v_order, s.u_count, s.v_count), std::tie(r.u_order, r.v_order, r.u_count, r.v_count)) << where;
      numbers(s.u_knots, r.u_knots, where);
      numbers(s.v_knots, r.v_knots, where);
      points(s.points, r.points, where);
      numbers(s.weights, r.weights, where);
      ASSERT_EQ(t->loops.size(), u.loops.size()) << where;
      for (size_t l = 0; l < t->loops.size(); ++l) {
        const TrimLoop &x = t->loops[l], &y = u.loops[l];
        EXPECT_EQ(x.edges, y.edges) << where;
        ASSERT_EQ(x.segments.size(), y.segments.size()) << where;
        for (size_t k = 0; k < x.segments.size(); ++k) {
          ASSERT_EQ(x.segments[k].index(), y.segments[k].index()) << where;
          if (const auto* c = std::get_if<NurbsCurve>(&x.segments[k])) {
            curve(*c, std::get<NurbsCurve>(y.segments[k]), where);
          } else {
            const auto &p = std::get<Polyline2D>(x.segments[k]).points, &q = std::get<Polyline2D>(y.segments[k]).points;
            ASSERT_EQ(p.size(), q.size()) << where;
            for (size_t i = 0; i < p.size(); ++i) number(p[i].x(), q[i].x(), where), number(p[i].y(), q[i].y(), where);
          }
        }
      }
    } else if (const auto* c = std::get_if<NurbsCurve>(&a)) {
      curve(*c, std::get<NurbsCurve>(b), where);
    } else if (const auto* m = std::get_if<TriangleMesh>(&a)) {
      const auto& n = std::get<TriangleMesh>(b);
      points(m->positions, n.positions, where);
      EXPECT_EQ(m->triangles, n.triangles) << where;
      points(m->corner_normals, n.corner_normals, where);
    } else {
      const auto &p = std::get<PolygonMesh>(a), &q = std::get<PolygonMesh>(b);
      points(p.positions, q.positions, where);
      EXPECT_EQ(p.polygons, q.polygons) << where;
    }
  }
  void node(const SceneNode& a, const SceneNode& b, const std::string& where) {
    EXPECT_EQ(a.name, b.name) << where;
    EXPECT_EQ(a.source_entity, b.source_entity) << where;
    for (int k = 0; k < 16; ++k) number(a.transform.matrix().data()[k], b.transform.matrix().data()[k], where);
    colour(a.colour, b.colour, where);
    ASSERT_EQ(a.shapes.size(), b.shapes.size()) << where;
    for (size_t i = 0; i < a.shapes.size(); ++i) {
      const Shape &s = a.shapes[i], &t = b.shapes[i];
      const std::string here = where + " shape " + std::to_string(i);
      EXPECT_EQ(s.name, t.name) << here;
      EXPECT_EQ(s.source_type, t.source_type) << here;
      EXPECT_EQ(s.source_entity, t.source_entity) << here;
      colour(s.colour, t.colour, here);
      geometry(s.geometry, t.geometry, here);
    }
    ASSERT_EQ(a.children.size(), b.children.size()) << where;
    for (size_t i = 0; i < a.children.size(); ++i) node(a.children[i], b.children[i], where + "/" + std::to_string(i));
  }
  void scene(const Scene& a, const Scene& b) {
    node(a.root, b.root, "root");
    EXPECT_EQ(a.unit.name, b.unit.name);
    number(a.unit.millimetres, b.unit.millimetres, "unit");
    EXPECT_EQ(a.source_unit.name, b.source_unit.name);
    number(a.source_unit.millimetres, b.source_unit.millimetres, "source unit");
  }
};

// Every geometry kind and field, odd values included: NaN, -0.0, infinities, a rotation, empty names.
Scene every_kind_scene() {
  Scene scene = capping_nurbs(bundled_capping(capping_shape_names().front()));
  SceneNode extra;
  extra.name = "extra";
  extra.source_entity = "solid 7";
  extra.transform = Eigen::Translation3d(1.0 / 3, -0.0, 1e300) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ());
  extra.colour = Colour{0.1, std::numeric_limits<double>::quiet_NaN(), 1.0};
  NurbsCurve curve;
  curve.order = 3;
  curve.knots = {0, 0, 0, 0.5, 1, 1, 1};
  curve.points = {{0, 0, 0}, {1, 2, 3}, {-0.0, 1e-310, 4}, {5, 6, std::numeric_limits<double>::infinity()}};
  curve.weights = {1, 0.7, 0.3, 1};
  extra.shapes.push_back({"curve", curve, Colour{0, 0, 1}, "BSplineCurve", "curve 1"});
  PolygonMesh polygons;
  polygons.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 2, 0}};
  polygons.polygons = {{0, 1, 2, 3}, {3, 2, 4}};
  extra.shapes.push_back({"", polygons, std::nullopt, "", ""});
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  mesh.corner_normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  extra.shapes.push_back({"mesh", mesh, std::nullopt, "Plane", "face 3 (mesh)"});
  TrimmedSurface trimmed;
  trimmed.surface.u_count = trimmed.surface.v_count = 2;
  trimmed.surface.u_knots = trimmed.surface.v_knots = {0, 0, 1, 1};
  trimmed.surface.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  TrimLoop loop;
  loop.segments = {Polyline2D{{{0, 0}, {1, 0}, {1, 1}}}, Polyline2D{{{1, 1}, {0, 0}}}};
  loop.edges = {{4, false}, {-1, true}};
  trimmed.loops = {loop};
  extra.children.push_back(SceneNode{"leaf", "", Eigen::Affine3d::Identity(), std::nullopt, {{"", trimmed}}, {}});
  scene.root.children.push_back(extra);
  scene.unit = {"in", 25.4};
  scene.source_unit = {"foot", 304.8};
  return scene;
}

TEST(SceneStream, EveryCappingSampleAndEveryKindReadBackBitIdentical) {
  for (const auto& name : capping_shape_names()) {
    const CappingDefinition capping = bundled_capping(name);
    for (Scene scene : {capping_nurbs(capping), Scene{}}) {
      if (scene.root.shapes.empty() && scene.root.children.empty())
        scene.root.shapes.push_back({name, capping_mesh(capping, 0.1), Colour{0.2, 0.3, 0.4}, "", "mesh"});
      Same same;
      same.scene(scene, read_scene_stream(write_scene_stream(scene), name));
      EXPECT_GT(same.doubles, 100) << name;
    }
  }
  const Scene scene = every_kind_scene();
  const std::string bytes = write_scene_stream(scene);
  Same same;
  same.scene(scene, read_scene_stream(bytes, "every kind"));
  const std::string again = write_scene_stream(read_scene_stream(bytes, "every kind"));
  ASSERT_EQ(again.size(), bytes.size());
  for (size_t i = 0; i < bytes.size(); ++i) ASSERT_EQ(again[i], bytes[i]) << "byte " << i;
}

TEST(SceneStream, CorpusStepTranslationReadBackBitIdentical) {
  const BrepTranslation read = read_step(CADNURBS_SHARED_DIR "/corpus/step/as1-oc-214.stp");
  ASSERT_GT(read.face_count, 0);
  BrepTranslation with_extras = read;  // the reader gave no fallback: make sure those fields travel too
  with_extras.fallbacks.push_back({"as1/solid 2", 3, "Plane", "no pcurve"});
  with_extras.repairs.push_back("as1/solid 2 face 3 (Plane): loop closed");
  const BrepTranslation back = read_translation_stream(write_translation_stream(with_extras), "as1");
  Same same;
  same.scene(read.scene, back.scene);
  EXPECT_GT(same.doubles, 10000);
  ASSERT_EQ(back.fallbacks.size(), with_extras.fallbacks.size());
  for (size_t i = 0; i < back.fallbacks.size(); ++i) {
    EXPECT_EQ(back.fallbacks[i].node, with_extras.fallbacks[i].node);
    EXPECT_EQ(back.fallbacks[i].face_index, with_extras.fallbacks[i].face_index);
    EXPECT_EQ(back.fallbacks[i].surface_type, with_extras.fallbacks[i].surface_type);
    EXPECT_EQ(back.fallbacks[i].reason, with_extras.fallbacks[i].reason);
  }
  EXPECT_EQ(back.repairs, with_extras.repairs);
  EXPECT_EQ(back.face_count, read.face_count);
  EXPECT_EQ(back.degenerated_edges, read.degenerated_edges);
}

std::string refusal(std::string_view bytes) {
  try {
    read_scene_stream(bytes, "s.bin");
  } catch (const FileError& e) {
    return e.what();
  }
  return "(read)";
}

TEST(SceneStream, DamagedStreamsAreRefusedWithOneLine) {
  const std::string bytes = write_scene_stream(every_kind_scene());
  EXPECT_EQ(refusal(""), "s.bin: not a scene stream (no CNSCENE magic)");
  EXPECT_EQ(refusal(write_translation_stream(BrepTranslation{})), "s.bin: not a scene stream (no CNSCENE magic)");
  EXPECT_EQ(refusal(bytes.substr(0, 10)), "s.bin: scene stream ends in the middle of the version at byte 8");
  std::string garbled = bytes;
  garbled[8] = 2;
  EXPECT_EQ(refusal(garbled), "s.bin: scene stream version 2 is not 1 at byte 8");
  garbled = bytes;
  for (int k = 0; k < 8; ++k) garbled[12 + k] = k == 7 ? 0x40 : 0;  // the root's name length: 2^62
  EXPECT_EQ(refusal(garbled), "s.bin: scene stream count 4611686018427387904 of node name needs 4611686018427387904 "
                              "bytes, more than the " + std::to_string(bytes.size() - 20) + " left at byte 12");
  EXPECT_EQ(refusal(bytes + "x"), "s.bin: scene stream has 1 byte after its end at byte " + std::to_string(bytes.size()));
  // Every truncation is refused, each with one line naming the stream.
  int refused = 0;
  for (size_t size = 0; size < bytes.size(); size += 1 + size / 64) {
    const std::string message = refusal(bytes.substr(0, size));
    refused += message.rfind("s.bin: ", 0) == 0 && message.find('\n') == std::string::npos;
  }
  int tried = 0;
  for (size_t size = 0; size < bytes.size(); size += 1 + size / 64) ++tried;
  EXPECT_EQ(refused, tried);
}

}  // namespace
}  // namespace cadnurbs
