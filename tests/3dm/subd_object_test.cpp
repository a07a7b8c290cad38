// ON_SubD objects: the six SubDs of each corpus logo file (archive 60 and 70) against measures taken apart
// from the reader (the level chunk's own component counts, Euler characteristic, edge use, orientation,
// Catmull-Clark's closed-form limit points against the ones Rhino cached), and a hand-built cube in the
// version 70 layout with the messages its corruptions are refused with.
#include "formats/3dm/subd_object.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "class_chunks.hpp"
#include "formats/3dm/rhino_scene.hpp"

namespace cadnurbs::rhino {
namespace {

constexpr const char* kSubdClass = "F09BA4D9-455B-42C3-BA3B-E6CCACEF853B";

// The archive id bounds level 0's header declares (vertices [b0, b1), edges [b1, b2), faces [b2, b3)),
// read here apart from read_subd: the component counts the file itself states.
std::array<std::uint32_t, 4> level_zero_bounds(ArchiveReader reader) {
  EXPECT_EQ(reader.u8(), 1);
  reader.begin_versioned_chunk(tcode::kAnonymousChunk);
  EXPECT_GE(reader.u32(), 1u);  // level count
  reader.skip(12 + 48);
  reader.begin_versioned_chunk(tcode::kAnonymousChunk);
  EXPECT_EQ(reader.u16(), 0);  // level index
  reader.skip(3 + 48);
  std::array<std::uint32_t, 4> bounds{};
  for (auto& b : bounds) b = reader.u32();
  return bounds;
}

using Edge = std::pair<int, int>;
Edge undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// How many faces use each edge, each direction counted apart.
std::map<Edge, int> directed_uses(const SubdControlNet& net) {
  std::map<Edge, int> uses;
  for (const auto& face : net.faces)
    for (std::size_t k = 0; k < face.size(); ++k) ++uses[{face[k], face[(k + 1) % face.size()]}];
  return uses;
}

std::map<Edge, int> undirected_uses(const SubdControlNet& net) {
  std::map<Edge, int> uses;
  for (const auto& [e, n] : directed_uses(net)) uses[undirected(e.first, e.second)] += n;
  return uses;
}

// Connected pieces of the net, faces joined by shared points.
int component_count(const SubdControlNet& net) {
  std::vector<int> parent(net.points.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int p) {
    while (parent[p] != p) p = parent[p] = parent[parent[p]];
    return p;
  };
  for (const auto& face : net.faces)
    for (int p : face) parent[root(p)] = root(face[0]);
  std::set<int> roots;
  for (const auto& face : net.faces) roots.insert(root(face[0]));
  return static_cast<int>(roots.size());
}

// Volume enclosed by the faces, each fanned from its first point: > 0 when they turn counter-clockwise
// seen from outside.
double signed_volume(const SubdControlNet& net) {
  double six_v = 0;
  for (const auto& f : net.faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k)
      six_v += net.points[f[0]].dot(net.points[f[k]].cross(net.points[f[k + 1]]));
  return six_v / 6;
}

struct CorpusSubd {
  RhinoSubd subd;
  std::array<std::uint32_t, 4> bounds;
};

std::vector<CorpusSubd> subds_in(const char* file) {
  const std::string bytes = testing::corpus_file(file);
  std::vector<CorpusSubd> out;
  for (const std::size_t offset : testing::class_chunk_offsets(bytes, kSubdClass)) {
    ArchiveReader reader = testing::reader_at_class_data(bytes, file, offset);
    const auto bounds = level_zero_bounds(reader);
    out.push_back({read_subd(reader), bounds});
    EXPECT_EQ(reader.bytes_left(), 0u) << file << " at " << offset;  // the whole class data was read past
  }
  return out;
}

class CorpusSubds : public ::testing::TestWithParam<const char*> {};

TEST_P(CorpusSubds, CountsTopologyAndOrientation) {
  const auto subds = subds_in(GetParam());
  ASSERT_EQ(subds.size(), 6u);
  for (std::size_t i = 0; i < subds.size(); ++i) {
    const SubdControlNet& net = subds[i].subd.net;
    const auto& b = subds[i].bounds;
    SCOPED_TRACE(std::string(GetParam()) + " SubD " + std::to_string(i));
    EXPECT_NO_THROW(validate(net, "net"));
    const auto edges = undirected_uses(net);
    EXPECT_EQ(net.points.size(), b[1] - b[0]);
    EXPECT_EQ(edges.size(), b[2] - b[1]);
    EXPECT_EQ(net.faces.size(), b[3] - b[2]);
    for (const auto& [e, n] : directed_uses(net)) EXPECT_EQ(n, 1) << "edge " << e.first << "-" << e.second;
    bool closed = true;
    std::size_t boundary = 0;
    for (const auto& [e, n] : edges) {
      EXPECT_TRUE(n == 1 || n == 2);
      closed = closed && n == 2;
      boundary += n == 1;
    }
    std::set<Edge> creases;
    for (const auto& [a, c] : net.crease_edges) creases.insert(undirected(a, c));
    EXPECT_EQ(creases.size(), net.crease_edges.size());
    for (const auto& [e, n] : edges)
      if (n == 1) EXPECT_TRUE(creases.count(e)) << "boundary edge " << e.first << "-" << e.second << " not a crease";
    const long euler =
        static_cast<long>(net.points.size()) - static_cast<long>(edges.size()) + static_cast<long>(net.faces.size());
    const double volume = signed_volume(net);
    if (closed) {  // each closed piece of genus g adds 2 - 2g
      EXPECT_EQ(euler % 2, 0);
      EXPECT_LE(euler, 2 * component_count(net));
      EXPECT_GT(volume, 0);
    }
    // Interior points where other than four faces meet, boundary points other than two.
    std::vector<int> valence(net.points.size(), 0), faces_at(net.points.size(), 0);
    for (const auto& [e, n] : edges) ++valence[e.first], ++valence[e.second];
    for (const auto& f : net.faces)
      for (int p : f) ++faces_at[p];
    int extraordinary = 0;
    for (std::size_t p = 0; p < net.points.size(); ++p)
      extraordinary += valence[p] == faces_at[p] ? faces_at[p] != 4 : faces_at[p] != 2;
    std::map<std::size_t, int> sizes;
    for (const auto& f : net.faces) ++sizes[f.size()];
    std::string by_size;
    for (const auto& [s, n] : sizes) by_size += " " + std::to_string(n) + "x" + std::to_string(s);
    std::cout << GetParam() << " SubD " << i << ": " << net.points.size() << " points, " << edges.size()
              << " edges, faces" << by_size << ", " << net.crease_edges.size() << " creases, "
              << net.corner_points.size() << " corners, " << (closed ? "closed" : "open") << " (" << boundary
              << " boundary edges, V-E+F " << euler << ", " << component_count(net) << " pieces, genus "
              << component_count(net) - euler / 2 << "), volume " << volume << ", " << extraordinary
              << " extraordinary points, " << subds[i].subd.limit_points.size() << " cached limit points\n";
  }
}

// Catmull-Clark's limit position where it has a closed form: a corner stays put; a point on a crease
// (exactly two crease edges) goes to (4P + A + B) / 6; a smooth point of valence n among quads only goes to
// (n^2 P + 4 (sum of edge neighbours) + (sum of opposite corners)) / (n (n + 5)) when its neighbours are
// smooth too (Rhino weights an edge ending at a crease point by its sector coefficient, which moves the
// next level's ring). Rhino's cached limit points must be there: this checks the points, faces (their
// order round each quad) and crease tags read.
TEST_P(CorpusSubds, CachedLimitPointsAreCatmullClarksClosedForms) {
  int checked = 0, crease_checked = 0;
  double worst = 0;
  for (const auto& corpus : subds_in(GetParam())) {
    const SubdControlNet& net = corpus.subd.net;
    std::map<int, std::vector<int>> crease_neighbours, edge_neighbours;
    std::map<int, std::vector<const std::vector<int>*>> faces_at;
    for (const auto& [a, b] : net.crease_edges) crease_neighbours[a].push_back(b), crease_neighbours[b].push_back(a);
    for (const auto& [e, n] : undirected_uses(net))
      edge_neighbours[e.first].push_back(e.second), edge_neighbours[e.second].push_back(e.first);
    for (const auto& f : net.faces)
      for (int p : f) faces_at[p].push_back(&f);
    const std::set<int> corners(net.corner_points.begin(), net.corner_points.end());
    for (const SubdLimitPoint& limit : corpus.subd.limit_points) {
      const int p = limit.point;
      const Eigen::Vector3d& P = net.points[p];
      std::optional<Eigen::Vector3d> expected;
      const auto& creases = crease_neighbours[p];
      if (corners.count(p)) {
        expected = P;
      } else if (creases.size() == 2) {
        expected = (4 * P + net.points[creases[0]] + net.points[creases[1]]) / 6;
        ++crease_checked;
      } else if (creases.empty() && faces_at[p].size() == edge_neighbours[p].size() &&
                 std::all_of(edge_neighbours[p].begin(), edge_neighbours[p].end(),
                             [&](int q) { return crease_neighbours[q].empty() && !corners.count(q); })) {
        bool quads = true;
        Eigen::Vector3d opposite = Eigen::Vector3d::Zero(), edge_sum = Eigen::Vector3d::Zero();
        for (const auto* f : faces_at[p]) {
          quads = quads && f->size() == 4;
          const std::size_t k = std::find(f->begin(), f->end(), p) - f->begin();
          if (f->size() == 4) opposite += net.points[(*f)[(k + 2) % 4]];
        }
        for (int q : edge_neighbours[p]) edge_sum += net.points[q];
        const double n = static_cast<double>(edge_neighbours[p].size());
        if (quads) expected = (n * n * P + 4 * edge_sum + opposite) / (n * (n + 5));
      }
      if (!expected) continue;
      ++checked;
      const double error = (limit.position - *expected).norm();
      worst = std::max(worst, error);
      EXPECT_LT(error, 1e-9 * std::max(1.0, P.norm())) << "point " << p;
      EXPECT_NEAR(limit.normal.norm(), 1.0, 1e-9);
    }
  }
  std::cout << GetParam() << ": " << checked << " cached limit points checked (" << crease_checked
            << " on creases), worst " << worst << "\n";
  EXPECT_GT(crease_checked, 0);
  EXPECT_GT(checked, crease_checked);
}

// Rhino's cached normals point to the side the faces turn counter-clockwise around: the side this reader
// calls outside. At a smooth point the cached normal nearly agrees with the area-weighted normal of the
// faces there; at a crease it is one sector's, so it is compared with the face there it agrees with best.
// Were the faces read the wrong way round, both would be negative.
TEST_P(CorpusSubds, CachedNormalsPointOutOfTheFaces) {
  double smooth_least = 1, crease_least = 1;
  for (const auto& corpus : subds_in(GetParam())) {
    const SubdControlNet& net = corpus.subd.net;
    std::vector<std::vector<Eigen::Vector3d>> face_areas(net.points.size());  // per point, its faces' area vectors
    for (const auto& f : net.faces) {
      Eigen::Vector3d area = Eigen::Vector3d::Zero();  // twice the area vector, by the shoelace rule
      for (std::size_t k = 0; k < f.size(); ++k) area += net.points[f[k]].cross(net.points[f[(k + 1) % f.size()]]);
      for (int p : f) face_areas[p].push_back(area);
    }
    std::vector<bool> on_crease(net.points.size(), false);
    for (const auto& [a, b] : net.crease_edges) on_crease[a] = on_crease[b] = true;
    for (const SubdLimitPoint& limit : corpus.subd.limit_points) {
      const auto& areas = face_areas[limit.point];
      if (on_crease[limit.point]) {
        double best = -1;
        for (const auto& a : areas) best = std::max(best, limit.normal.dot(a.normalized()));
        crease_least = std::min(crease_least, best);
      } else {
        const Eigen::Vector3d sum =
            std::accumulate(areas.begin(), areas.end(), Eigen::Vector3d(Eigen::Vector3d::Zero()));
        smooth_least = std::min(smooth_least, limit.normal.dot(sum.normalized()));
      }
    }
  }
  std::cout << GetParam() << ": least cosine of a cached normal to its faces' mean normal " << smooth_least
            << " (smooth points), to its nearest face normal " << crease_least << " (crease points)\n";
  EXPECT_GT(smooth_least, 0.5);
  EXPECT_GT(crease_least, 0.5);
}

INSTANTIATE_TEST_SUITE_P(SubdObject, CorpusSubds, ::testing::Values("v6_rhino_subd_logo.3dm", "v7_rhino_logo_subd.3dm"),
                         [](const auto& info) { return std::string(info.param).substr(0, 2); });

// Both logo files hold the same six SubDs (in opposite order): the same nets, read from two layouts.
TEST(SubdObject, Version60And70FilesHoldTheSameNets) {
  const auto v6 = subds_in("v6_rhino_subd_logo.3dm");
  const auto v7 = subds_in("v7_rhino_logo_subd.3dm");
  ASSERT_EQ(v6.size(), v7.size());
  for (std::size_t i = 0; i < v6.size(); ++i) {
    const SubdControlNet& a = v6[i].subd.net;
    const SubdControlNet& b = v7[v7.size() - 1 - i].subd.net;
    SCOPED_TRACE("SubD " + std::to_string(i));
    ASSERT_EQ(a.points.size(), b.points.size());
    double worst = 0;
    for (std::size_t p = 0; p < a.points.size(); ++p) worst = std::max(worst, (a.points[p] - b.points[p]).norm());
    EXPECT_EQ(worst, 0.0);
    EXPECT_EQ(a.faces, b.faces);
    EXPECT_EQ(a.crease_edges, b.crease_edges);
    EXPECT_EQ(a.corner_points, b.corner_points);
  }
}

// The scene keeps a node per SubD (no shapes), lists the nets in millimetres, and warns of none.
TEST(SubdObject, SceneListsTheNets) {
  for (const char* file : {"v6_rhino_subd_logo.3dm", "v7_rhino_logo_subd.3dm"}) {
    const Rhino3dmFile parsed = read_3dm_file(CADNURBS_SHARED_DIR "/corpus/3dm/" + std::string(file));
    const RhinoScene scene = scene_from_3dm(parsed, "logo");
    ASSERT_EQ(scene.subd_objects.size(), 6u) << file;
    for (const auto& w : scene.warnings) EXPECT_EQ(w.find("ON_SubD"), std::string::npos) << w;
    std::set<std::string> nodes;
    std::function<void(const SceneNode&)> walk = [&](const SceneNode& n) {
      if (n.shapes.empty() && n.children.empty()) nodes.insert(n.source_entity);
      for (const auto& c : n.children) walk(c);
    };
    walk(scene.scene.root);
    std::size_t k = 0;
    for (const auto& object : parsed.objects) {
      const auto* subd = std::get_if<RhinoSubd>(&object.geometry);
      if (!subd) continue;
      const auto& listed = scene.subd_objects.at(k++);
      EXPECT_EQ(listed.source_entity, "object " + std::to_string(object.index));
      EXPECT_TRUE(nodes.count(listed.source_entity)) << listed.source_entity;
      EXPECT_EQ(listed.object_label.rfind(listed.source_entity, 0), 0u);
      ASSERT_EQ(listed.net.points.size(), subd->net.points.size());
      for (std::size_t p = 0; p < listed.net.points.size(); ++p)
        EXPECT_EQ(listed.net.points[p], subd->net.points[p] * parsed.unit.millimetres);
      EXPECT_EQ(listed.stored_limit_points.size(), subd->limit_points.size());
    }
  }
}

// A SubD in an inch file: its node sits under its layer with the object's name and no shapes; the net and
// limit points come out in millimetres (x 25.4), the rest (faces, creases, corners, normals) as read.
TEST(SubdObject, SceneScalesTheNetToMillimetres) {
  RhinoSubd subd;
  subd.net.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  subd.net.faces = {{0, 1, 2}};
  subd.net.crease_edges = {{0, 1}};
  subd.net.corner_points = {2};
  subd.limit_points = {{1, {0.5, 0.25, 0}, {0, 0, 1}}};
  Rhino3dmFile file;
  file.unit = {"inch", 25.4};
  file.layers = {{"Default", Colour{}}, {"Nets", Colour{0, 1, 0}}};
  file.objects.push_back({0, "ON_SubD", subd, {"fin", 1, std::nullopt}});
  const RhinoScene read = scene_from_3dm(file, "part");
  EXPECT_TRUE(read.warnings.empty());
  ASSERT_EQ(read.subd_objects.size(), 1u);
  const auto& listed = read.subd_objects[0];
  EXPECT_EQ(listed.source_entity, "object 0");
  EXPECT_EQ(listed.object_label, "object 0 'fin'");
  ASSERT_EQ(listed.net.points.size(), 3u);
  for (std::size_t p = 0; p < 3; ++p) EXPECT_EQ(listed.net.points[p], subd.net.points[p] * 25.4);
  EXPECT_EQ(listed.net.faces, subd.net.faces);
  EXPECT_EQ(listed.net.crease_edges, subd.net.crease_edges);
  EXPECT_EQ(listed.net.corner_points, subd.net.corner_points);
  ASSERT_EQ(listed.stored_limit_points.size(), 1u);
  EXPECT_EQ(listed.stored_limit_points[0].point, 1);
  EXPECT_EQ(listed.stored_limit_points[0].position, Eigen::Vector3d(0.5, 0.25, 0) * 25.4);
  EXPECT_EQ(listed.stored_limit_points[0].normal, Eigen::Vector3d(0, 0, 1));
  ASSERT_EQ(read.scene.root.children.size(), 1u);
  const SceneNode& layer = read.scene.root.children[0];
  EXPECT_EQ(layer.name, "Nets");
  ASSERT_EQ(layer.children.size(), 1u);
  EXPECT_EQ(layer.children[0].name, "fin");
  EXPECT_EQ(layer.children[0].source_entity, "object 0");
  EXPECT_TRUE(layer.children[0].shapes.empty());
}

// A SubD's class data in the archive 70 layout, with the chunks' CRCs: points, faces as point loops
// (edges are made in order of first use, each face referring to its edges with a flag when it runs along
// one backwards), crease edges and corner points.
struct HandSubd {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> faces;
  std::set<Edge> creases;
  std::set<int> corners;
  // What files may hold beyond the cube: every component's base with a group id (4 bytes), a symmetry
  // link (5 bytes) and an anonymous chunk as additions, and a second level after level 0.
  bool with_extras = false;

  static std::string crc_chunk(const std::string& own, const std::string& nested) {
    testing::ClassData c;
    c.put(tcode::kAnonymousChunk).put(static_cast<std::int64_t>(own.size() + nested.size() + 4));
    c.body += own + nested;
    c.put(static_cast<std::uint32_t>(
        ::crc32(0, reinterpret_cast<const Bytef*>(own.data()), static_cast<uInt>(own.size()))));
    return c.body;
  }
  void base(testing::ClassData& d, std::uint32_t archive_id) const {
    d.put(archive_id).put(archive_id).put(std::uint16_t{0});
    if (with_extras) {
      d.put(std::uint8_t{0});                               // no displacement
      d.put(std::uint8_t{4}).put(7u);                       // group id
      d.put(std::uint8_t{5}).put(1u).put(std::uint8_t{0});  // symmetry link
      d.put(std::uint8_t{254});
      d.body += crc_chunk("future", "");
    }
    d.put(std::uint8_t{255});
  }

  std::string class_data() const {
    std::vector<Edge> edges;
    std::map<Edge, std::uint32_t> edge_id;
    const auto nv = static_cast<std::uint32_t>(points.size());
    for (const auto& f : faces)
      for (std::size_t k = 0; k < f.size(); ++k)
        if (edge_id.emplace(undirected(f[k], f[(k + 1) % f.size()]), 0).second)
          edges.push_back(undirected(f[k], f[(k + 1) % f.size()]));
    for (std::size_t e = 0; e < edges.size(); ++e) edge_id[edges[e]] = nv + 1 + static_cast<std::uint32_t>(e);
    const auto ne = static_cast<std::uint32_t>(edges.size()), nf = static_cast<std::uint32_t>(faces.size());
    testing::ClassData level;
    level.put(1).put(1).put(std::uint16_t{0}).put(std::uint8_t{4}).put(std::uint8_t{4}).put(std::uint8_t{4});
    level.doubles({0, 0, 0, 1, 1, 1});
    level.put(1u).put(nv + 1).put(nv + ne + 1).put(nv + ne + nf + 1);
    for (std::uint32_t v = 0; v < nv; ++v) {
      base(level, v + 1);
      level.put(static_cast<std::uint8_t>(corners.count(static_cast<int>(v)) ? 3 : 1));
      level.doubles({points[v].x(), points[v].y(), points[v].z()});
      level.put(std::uint16_t{0}).put(std::uint16_t{0}).put(std::uint8_t{0});  // edges, faces, limit points
      level.put(std::uint16_t{0}).put(std::uint16_t{0}).put(std::uint8_t{255});
    }
    for (const Edge& e : edges) {
      base(level, edge_id.at(e));
      level.put(static_cast<std::uint8_t>(creases.count(e) ? 2 : 1)).put(std::uint16_t{0});
      level.doubles({0, 0, 0});
      level.put(std::uint16_t{2}).put(static_cast<std::uint32_t>(e.first + 1)).put(std::uint8_t{0});
      level.put(static_cast<std::uint32_t>(e.second + 1)).put(std::uint8_t{0});
      level.put(std::uint16_t{0}).put(std::uint8_t{255});
    }
    for (std::uint32_t f = 0; f < nf; ++f) {
      const auto& face = faces[f];
      base(level, nv + ne + 1 + f);
      level.put(0u).put(0u);
      level.put(static_cast<std::uint16_t>(face.size())).put(static_cast<std::uint16_t>(face.size()));
      for (std::size_t k = 0; k < face.size(); ++k) {
        const int a = face[k], b = face[(k + 1) % face.size()];
        level.put(edge_id.at(undirected(a, b))).put(static_cast<std::uint8_t>(a > b ? 1 : 0));
      }
      level.put(std::uint8_t{255});
    }
    level.put(std::uint8_t{0});  // no cached mesh
    testing::ClassData subdimple;
    subdimple.put(1).put(0).put(with_extras ? 2u : 1u).put(nv).put(ne).put(nf).doubles({0, 0, 0, 1, 1, 1});
    std::string levels = crc_chunk(level.body, "");
    if (with_extras) {
      std::string finer = level.body;
      finer[8] = 1;  // its level index
      levels += crc_chunk(finer, "");
    }
    testing::ClassData data;
    data.put(std::uint8_t{1});
    data.body += crc_chunk(subdimple.body, levels);
    return data.body;
  }
};

HandSubd unit_cube() {
  HandSubd cube;
  for (int k = 0; k < 8; ++k) cube.points.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  cube.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  cube.creases = {{0, 1}, {1, 3}};
  cube.corners = {1};
  return cube;
}

// The one-line message read_subd refuses hand-built class data with, or "no error".
std::string read_error(const std::string& class_data) {
  return testing::error_of(testing::ClassData{class_data}.chunk(), read_subd);
}

// The hand-built SubD read back: the cube's net exactly, every byte of its class data used.
void expect_cube_reads_back(const HandSubd& cube) {
  const std::string bytes = testing::ClassData{cube.class_data()}.chunk();
  ArchiveReader reader(bytes, "hand.3dm", 70);
  reader.begin_chunk();
  const RhinoSubd read = read_subd(reader);
  EXPECT_EQ(reader.bytes_left(), 0u);
  EXPECT_EQ(read.net.points, cube.points);
  EXPECT_EQ(read.net.faces, cube.faces);
  std::set<Edge> creases;
  for (const auto& [a, b] : read.net.crease_edges) creases.insert(undirected(a, b));
  EXPECT_EQ(creases, cube.creases);
  EXPECT_EQ(read.net.corner_points, std::vector<int>(cube.corners.begin(), cube.corners.end()));
  EXPECT_TRUE(read.limit_points.empty());
  EXPECT_DOUBLE_EQ(signed_volume(read.net), 1.0);
}

TEST(SubdObject, HandBuiltCubeReadsBack) { expect_cube_reads_back(unit_cube()); }

// Additions a reader does not know and a finer level are stepped over: the same net comes back.
TEST(SubdObject, AdditionsAndFinerLevelsAreSteppedOver) {
  HandSubd cube = unit_cube();
  cube.with_extras = true;
  expect_cube_reads_back(cube);
}

// Offsets in the messages: the class chunk's 12-byte header, the present byte at 12, the SubD chunk at 13
// (12-byte header, 8 bytes of versions, 4 + 12 + 48 bytes), so the level chunk's header is at 97 and its
// first vertex at 97 + 12 + 8 + 2 + 3 + 48 + 16 = 186; the vertex's tag follows its 11-byte base.
TEST(SubdObject, CorruptionsAreRefusedWithOneLine) {
  const std::string good = unit_cube().class_data();
  ASSERT_EQ(read_error(good), "no error");

  std::string bad_tag = good;
  bad_tag[186 - 12 + 11] = 9;  // class data starts at file offset 12
  EXPECT_EQ(read_error(bad_tag), "hand.3dm: chunk 0x40008000 at offset 97: ON_SubD: vertex 0 has unknown tag 9");

  std::string crossed = good;
  // The first face's first edge reference (archive id 9, edge 0-2) made the cube's edge 1-3 (id 11):
  // its loop no longer joins end to end.
  const std::string id9("\x09\x00\x00\x00\x00", 5), id11("\x0b\x00\x00\x00\x00", 5);
  const std::size_t first_face_ref = crossed.rfind(id9);
  ASSERT_NE(first_face_ref, std::string::npos);
  crossed.replace(first_face_ref, 5, id11);
  EXPECT_EQ(read_error(crossed),
            "hand.3dm: chunk 0x40008000 at offset 97: ON_SubD: face 0: edge 0 ends at vertex 3, the next starts at "
            "vertex 2");

  // Cut after 300 bytes: the SubD chunk (the class data but its first byte) says it is longer than what is left.
  EXPECT_EQ(read_error(good.substr(0, 300)),
            "hand.3dm: chunk 0x40008000 at offset 13: length " + std::to_string(good.size() - 1 - 12) +
                " runs past the end of the enclosing chunk (" + std::to_string(300 - 1 - 12) + " bytes left)");

  // The last archive id bound (at file offset 182) made huge: refused before anything is allocated.
  std::string huge = good;
  const std::uint32_t bound = 0x7fffffff;
  std::memcpy(huge.data() + 182 - 12, &bound, 4);
  const std::string message = read_error(huge);
  const std::string prefix =
      "hand.3dm: chunk 0x40008000 at offset 97: ON_SubD: 2147483646 components cannot fit in the ";
  EXPECT_EQ(message.substr(0, prefix.size()), prefix);
  EXPECT_EQ(message.substr(message.size() - 11), " bytes left");

  // The same bytes in an archive 80 file.
  const std::string framed = testing::ClassData{good}.chunk();
  const auto read_as_version_80 = [&](ArchiveReader&) {
    ArchiveReader reader(framed, "hand.3dm", 80);
    reader.begin_chunk();
    read_subd(reader);
  };
  EXPECT_EQ(testing::error_of(framed, read_as_version_80),
            "hand.3dm: chunk 0x00027FFA at offset 0: ON_SubD: archive version 80 is not read (only 60 and 70)");
}

}  // namespace
}  // namespace cadnurbs::rhino
