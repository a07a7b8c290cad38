// The NURSS text file (formats/nurss/nurss_text) and the report's NURSS figures (nurss_figures): a bit-exact
// round trip of the capping's NURSS, the float count of the written text against the thesis's count, exact
// messages for damaged files, the limit mesh within D away from the n-gons, and the refusal of nets that are
// not quadratic.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/nurss_figures.hpp"
#include "analysis/nurss/nurss_from_nurbs.hpp"
#include "analysis/nurss/nurss_limit_mesh.hpp"
#include "formats/nurss/nurss_text.hpp"
#include "formats/common/file_io.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

const std::string kCapping90 = CADNURBS_SOURCE_DIR "/samples/capping-90.x3dv";

const NurbsSurface& body_of(const Scene& scene) {
  for (const auto& s : scene.root.shapes)
    if (s.name == "body") return std::get<TrimmedSurface>(s.geometry).surface;
  for (const auto& c : scene.root.children)
    for (const auto& s : c.shapes)
      if (s.name == "body") return std::get<TrimmedSurface>(s.geometry).surface;
  throw std::runtime_error("no body");
}

NurssMesh capping90_nurss() {
  NurssMesh mesh = nurss_from_nurbs({body_of(read_vrml(kCapping90))}, 1e-6);
  fill_boundary_loops(mesh, 1);
  return mesh;
}

// The message of the FileError that reading `text` throws, or "" when it reads.
std::string read_error(const std::string& text) {
  try {
    read_nurss_text(text, "damaged.nurss");
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

TEST(NurssText, RoundTripIsBitExact) {
  const NurssMesh mesh = capping90_nurss();
  const LengthUnit inch{"in", 25.4};
  const std::string text = write_nurss_text(mesh, inch);
  LengthUnit unit;
  const NurssMesh read = read_nurss_text(text, "capping-90.nurss", &unit);
  EXPECT_EQ(unit.name, "in");
  EXPECT_EQ(unit.millimetres, 25.4);
  ASSERT_EQ(read.vertex_count(), mesh.vertex_count());
  ASSERT_EQ(read.face_count(), mesh.face_count());
  ASSERT_EQ(read.edge_count(), mesh.edge_count());
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const NurssVertexId id(v);
    EXPECT_EQ(read.position(id), mesh.position(id)) << "vertex " << v;
    EXPECT_EQ(read.weight(id), mesh.weight(id)) << "vertex " << v;
  }
  int ngons = 0;
  for (int f = 0; f < mesh.face_count(); ++f) {
    const NurssFaceId id(f);
    ASSERT_EQ(read.corners(id), mesh.corners(id)) << "face " << f;
    EXPECT_EQ(read.label(id), mesh.label(id)) << "face " << f;
    ngons += mesh.label(id) == 1;
    const auto& c = mesh.corners(id);
    for (size_t k = 0; k < c.size(); ++k) {
      const NurssVertexId a = c[k], b = c[(k + 1) % c.size()];
      EXPECT_EQ(read.interval(a, b), mesh.interval(a, b));
      EXPECT_EQ(read.interval(b, a), mesh.interval(b, a));
    }
  }
  EXPECT_EQ(ngons, 2);
  EXPECT_EQ(write_nurss_text(read, inch), text);
}

TEST(NurssText, OpenMeshKeepsItsBoundaryIntervals) {
  // The capping's body without its n-gons: the boundary sides' outer intervals are in the open-sides section.
  const NurssMesh mesh = nurss_from_nurbs({body_of(read_vrml(kCapping90))}, 1e-6);
  const NurssMesh read = read_nurss_text(write_nurss_text(mesh), "open.nurss");
  ASSERT_EQ(read.edge_count(), mesh.edge_count());
  int open = 0;
  for (int e = 0; e < mesh.edge_count(); ++e) {
    const NurssEdge& a = mesh.edge(NurssEdgeId(e));
    const auto at = read.find_edge(a.ends[0], a.ends[1]);
    ASSERT_TRUE(at);
    const NurssEdge& b = read.edge(*at);
    EXPECT_EQ(b.intervals[0], a.intervals[0]);
    EXPECT_EQ(b.intervals[1], a.intervals[1]);
    open += !mesh.face_with_side(a.ends[0], a.ends[1]) || !mesh.face_with_side(a.ends[1], a.ends[0]);
  }
  EXPECT_GT(open, 0);
}

// Values on the lines of a section: from the line after "<keyword> <count>", <count> lines.
long values_in_section(const std::string& text, const std::string& keyword) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(keyword + " ", 0) == 0) break;
  const long lines = std::stol(line.substr(keyword.size() + 1));
  long values = 0;
  for (long k = 0; k < lines && std::getline(in, line); ++k) {
    std::istringstream words(line);
    std::string word;
    while (words >> word) ++values;
  }
  return values;
}

TEST(NurssFigures, FloatCountIsWhatTheWrittenFileHolds) {
  const auto figures = nurss_figures(read_vrml(kCapping90), 1.0);
  ASSERT_TRUE(figures);
  const long vertex_values = values_in_section(figures->text, "vertices");
  const long interval_values = values_in_section(figures->text, "intervals");
  const long corner_values = values_in_section(figures->text, "faces");
  EXPECT_EQ(vertex_values, 4 * figures->storage.control_points);
  EXPECT_EQ(interval_values, figures->storage.knot_intervals);
  EXPECT_EQ(vertex_values + interval_values, figures->storage.floats);
  EXPECT_EQ(values_in_section(figures->text, "open-sides"), 0);  // closed by its n-gons
  EXPECT_EQ(corner_values + figures->storage.faces, figures->storage.connectivity_integers);
  EXPECT_EQ(figures->text_bytes, static_cast<long>(figures->text.size()));
  EXPECT_LT(figures->gzip_bytes, figures->text_bytes);
  // The text reads back as the NURSS the figures count.
  const NurssMesh read = read_nurss_text(figures->text, "capping-90.nurss");
  EXPECT_EQ(read.vertex_count(), figures->storage.control_points);
  EXPECT_EQ(read.edge_count(), figures->storage.edges);
}

TEST(NurssText, DamagedFilesGiveOneLineMessages) {
  NurssMesh mesh;
  const NurssVertexId a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({1, 0, 0}), c = mesh.add_vertex({0, 1, 0}, 2);
  mesh.add_face({a, b, c});
  mesh.set_interval(a, b, 1);
  mesh.set_interval(b, c, 2);
  mesh.set_interval(c, a, 0.5);
  mesh.set_interval(b, a, 1);
  mesh.set_interval(c, b, 2);
  mesh.set_interval(a, c, 0.5);
  const std::string good = write_nurss_text(mesh);
  ASSERT_EQ(good,
            "#NURSS 1 quadratic\nunit mm 1\nvertices 3\n0 0 0 1\n1 0 0 1\n0 1 0 2\nfaces 1\n0 1 2\nlabels 0\n"
            "intervals 1\n1 2 .5\nopen-sides 3\n1 0 1\n2 1 2\n0 2 .5\n");
  EXPECT_EQ(read_error(good), "");
  auto damaged = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return read_error(text.replace(at, from.size(), to));
  };
  EXPECT_EQ(read_error("#VRML V2.0 utf8\n"),
            "damaged.nurss: line 1: not a NURSS text file (the first line must be '#NURSS 1 quadratic')");
  EXPECT_EQ(damaged("0 1 0 2\n", "0 1 0 0\n"), "damaged.nurss: line 6: vertex 2 has weight 0; weights must be > 0");
  EXPECT_EQ(damaged("vertices 3", "vertices 3000000000"),
            "damaged.nurss: line 3: vertices count 3000000000 exceeds the 12 lines left");
  EXPECT_EQ(damaged("0 1 2\n", "0 1 7\n"), "damaged.nurss: line 8: corner index 7 names no vertex (3 vertices)");
  EXPECT_EQ(damaged("0 1 2\n", "0 1 1\n"), "damaged.nurss: line 8: NURSS face 0: repeats vertex 1");
  EXPECT_EQ(damaged("1 2 .5\n", "1 x .5\n"), "damaged.nurss: line 11: knot interval 'x' is not a number");
  EXPECT_EQ(damaged("1 2 .5\n", "1 2\n"), "damaged.nurss: line 11: face 0 has 3 corners but 2 intervals");
  EXPECT_EQ(damaged("0 2 .5\n", ""), "damaged.nurss: line 12: open-sides count 3 exceeds the 2 lines left");
  EXPECT_EQ(read_error(good.substr(0, good.find("labels"))),
            "damaged.nurss: line 9: the file ends where the 'labels' line should be");
  EXPECT_EQ(damaged("open-sides 3\n1 0 1\n2 1 2\n0 2 .5\n", "open-sides 0\n"),
            "damaged.nurss: at the end: NURSS mesh: edge 0-1: vertex 1 holds no knot interval >= 0");
  EXPECT_EQ(damaged("0 2 .5\n", "0 2 .5\nmore\n"), "damaged.nurss: line 16: unexpected text after the last section");
}

TEST(NurssFigures, Capping90WithinOneMillimetreAwayFromTheNgons) {
  std::string why_not;
  const auto figures = nurss_figures(read_vrml(kCapping90), 1.0, &why_not);
  ASSERT_TRUE(figures) << why_not;
  std::printf("[ figures ] capping-90 NURSS at D = 1 mm: %d levels, %ld floats, %ld text bytes (%ld gzip'd), %zu "
              "triangles; away from the n-gons mesh->NURBS %.3g mm; whole mesh vs body + lids %.3g / %.3g mm\n",
              figures->levels, figures->storage.floats, figures->text_bytes, figures->gzip_bytes,
              figures->limit_mesh.triangles.size(), figures->away_from_ngons.mesh_to_surface.max,
              figures->whole.mesh_to_surface.max, figures->whole.surface_to_mesh.max);
  EXPECT_EQ(figures->quadratic_surfaces, 1);
  EXPECT_EQ(figures->lids, 2);
  EXPECT_EQ(figures->ngon_faces, 2);
  EXPECT_TRUE(figures->within_max_deviation);
  EXPECT_GE(figures->levels, 1);
  EXPECT_LE(figures->away_from_ngons.mesh_to_surface.max, 1.0);
  EXPECT_GT(figures->away_from_ngons.mesh_to_surface.samples, static_cast<long>(figures->limit_mesh.triangles.size()));
  EXPECT_LE(figures->whole.overall.max, 1.0);  // capping-90's profile is convex: its n-gons stay on the lids
  EXPECT_EQ(figures->triangle_labels.size(), figures->limit_mesh.triangles.size());
  // The smallest level: one level fewer is measured farther than D.
  Scene body;
  body.root.shapes.push_back({"body", TrimmedSurface{body_of(read_vrml(kCapping90)), {}}, std::nullopt});
  const TriangleMesh coarser = nurss_triangles_with_label(nurss_limit_mesh(capping90_nurss(), figures->levels - 1), 0);
  EXPECT_GT(measure_deviation(coarser, body).mesh_to_surface.max, 1.0);
}

TEST(NurssFigures, RefusesNetsThatAreNotQuadratic) {
  // A twisted bilinear patch: order 2 x 2 and not planar.
  NurbsSurface twisted;
  twisted.u_count = twisted.v_count = 2;
  twisted.u_knots = twisted.v_knots = {0, 0, 1, 1};
  twisted.points = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 5}};
  Scene scene;
  scene.root.shapes.push_back({"saddle", TrimmedSurface{twisted, {}}, std::nullopt});
  std::string why_not;
  EXPECT_FALSE(nurss_figures(scene, 1.0, &why_not));
  EXPECT_EQ(why_not,
            "surface 'saddle' is of order 2 x 2 and not planar; a quadratic NURSS needs order 3 x 3 (planar lids "
            "become n-gon faces)");
  // Flat, it is a lid; with nothing else there is nothing to make a NURSS of.
  std::get<TrimmedSurface>(scene.root.shapes[0].geometry).surface.points[3].z() = 0;
  EXPECT_FALSE(nurss_figures(scene, 1.0, &why_not));
  EXPECT_EQ(why_not, "no order-3 x 3 surface: nothing to make a quadratic NURSS of");
}

}  // namespace
}  // namespace cadnurbs
