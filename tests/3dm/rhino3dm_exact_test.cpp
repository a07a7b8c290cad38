// Files written by another program: McNeel's rhino3dm (openNURBS in WebAssembly, from npm) wrote the .3dm
// files in RHINO3DM_GENERATED_DIR (tests/3dm/generate/generate.mjs, run by the ctest fixture
// 3dm.generate_rhino3dm_files) in every archive version it writes, and beside each a JSON file with what it
// reads back: class, name, layer, units, and every order, count, knot, control point and weight as the
// shortest decimal that reads back as the same double. Our reader must recover the stored doubles bit for bit.
//
// Conventions compared: openNURBS stores order + count - 2 knots, core keeps count + order (the two ends
// duplicated); rhino3dm's points are homogeneous [w x, w y, w z, w] as stored, core keeps Euclidean points,
// which must be the stored values times (1 / w) (one reciprocal, as openNURBS's GetCV forms them).
// Objects that are not NURBS in the file (lines, polylines: exact; revolutions, plane surfaces: computed
// NURBS forms) are marked in the JSON; computed forms are compared to 1e-12 relative.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "formats/3dm/rhino_file.hpp"

namespace {

using cadnurbs::NurbsCurve;
using cadnurbs::NurbsSurface;
using cadnurbs::TriangleMesh;
using cadnurbs::rhino::RhinoBrep;
using nlohmann::json;

const std::string kDir = RHINO3DM_GENERATED_DIR;

json load_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    ADD_FAILURE() << path << " is missing: run the ctest fixture 3dm.generate_rhino3dm_files (or node "
                  << CADNURBS_SOURCE_DIR "/tests/3dm/generate/generate.mjs " << kDir << ")";
    return json();
  }
  return json::parse(in);
}

std::string bits(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g (0x%016llx)", x,
                static_cast<unsigned long long>(std::bit_cast<std::uint64_t>(x)));
  return text;
}

// Bit-equal (so 0 and -0 differ), or within 1e-12 relative when `exact` is false.
::testing::AssertionResult same(double got, double want, bool exact) {
  if (exact ? std::bit_cast<std::uint64_t>(got) == std::bit_cast<std::uint64_t>(want)
            : std::abs(got - want) <= 1e-12 * std::max(1.0, std::abs(want)))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "got " << bits(got) << ", want " << bits(want)
                                       << (exact ? " (bit-equal)" : " (1e-12)");
}

// Core's full knot vector against openNURBS's (no end knots): the inner values equal, the ends duplicated.
void expect_knots(const std::vector<double>& full, const json& stored, bool exact, const std::string& what) {
  ASSERT_EQ(full.size(), stored.size() + 2) << what;
  for (std::size_t i = 0; i < stored.size(); ++i)
    EXPECT_TRUE(same(full[i + 1], stored[i].get<double>(), exact)) << what << " knot " << i + 1;
  EXPECT_TRUE(same(full.front(), full[1], true)) << what << ": first knot is not a copy of the second";
  EXPECT_TRUE(same(full.back(), full[full.size() - 2], true)) << what << ": last knot is not a copy of the one before";
}

// One control point: rhino3dm's homogeneous [wx, wy, wz, w] against core's Euclidean point and weight.
void expect_point(const Eigen::Vector3d& point, double weight, bool rational, const json& stored, int dimension,
                  bool exact, const std::string& what) {
  const double w = stored[3].get<double>();
  if (rational) {
    EXPECT_TRUE(same(weight, w, exact)) << what << " weight";
  } else {
    EXPECT_TRUE(same(w, 1.0, true)) << what << ": rhino3dm reports a weight on a polynomial object";
  }
  const double r = rational ? 1.0 / w : 1.0;
  for (int d = 0; d < 3; ++d) {
    const double want = d < dimension ? stored[d].get<double>() * r : 0.0;
    EXPECT_TRUE(same(point[d], want, exact)) << what << " coordinate " << d;
  }
}

void expect_curve(const NurbsCurve& curve, const json& expected, bool exact, const std::string& what) {
  ASSERT_EQ(curve.dimension, expected["dimension"].get<int>()) << what;
  ASSERT_EQ(curve.order, expected["order"].get<int>()) << what;
  ASSERT_EQ(curve.count(), expected["count"].get<int>()) << what;
  const bool rational = expected["rational"].get<bool>();
  ASSERT_EQ(curve.is_rational(), rational) << what;
  expect_knots(curve.knots, expected["knots"], exact, what);
  for (int i = 0; i < curve.count(); ++i)
    expect_point(curve.points[i], curve.weight(i), rational, expected["points"][i], curve.dimension, exact,
                 what + " point " + std::to_string(i));
}

void expect_surface(const NurbsSurface& surface, const json& expected, bool exact, const std::string& what) {
  ASSERT_EQ(surface.u_order, expected["order_u"].get<int>()) << what;
  ASSERT_EQ(surface.v_order, expected["order_v"].get<int>()) << what;
  ASSERT_EQ(surface.u_count, expected["count_u"].get<int>()) << what;
  ASSERT_EQ(surface.v_count, expected["count_v"].get<int>()) << what;
  ASSERT_EQ(surface.points.size(), static_cast<std::size_t>(surface.u_count * surface.v_count)) << what;
  const bool rational = expected["rational"].get<bool>();
  ASSERT_EQ(surface.is_rational(), rational) << what;
  expect_knots(surface.u_knots, expected["knots_u"], exact, what + " u");
  expect_knots(surface.v_knots, expected["knots_v"], exact, what + " v");
  for (int j = 0; j < surface.v_count; ++j)
    for (int i = 0; i < surface.u_count; ++i)
      expect_point(surface.point(i, j), surface.weight(i, j), rational, expected["points"][surface.index(i, j)], 3,
                   exact, what + " point (" + std::to_string(i) + ", " + std::to_string(j) + ")");
}

// Positions are float32 in the file: compared as floats. A quad becomes two triangles of its own corners,
// a triangle one, in face order.
void expect_mesh(const TriangleMesh& mesh, const json& expected, const std::string& what) {
  const json& vertices = expected["vertices"];
  ASSERT_EQ(mesh.positions.size(), vertices.size()) << what;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(static_cast<float>(mesh.positions[i][d]), static_cast<float>(vertices[i][d].get<double>()))
          << what << " vertex " << i << " coordinate " << d;
  const json& faces = expected["faces"];
  std::size_t want_triangles = 0;
  for (const json& face : faces) want_triangles += face.size() - 2;
  ASSERT_EQ(want_triangles, faces.size() + expected["quad_count"].get<std::size_t>()) << what;
  ASSERT_EQ(mesh.triangles.size(), want_triangles) << what;
  std::size_t t = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::set<int> corners = faces[f].get<std::set<int>>();
    std::set<int> used;
    for (std::size_t k = 0; k + 2 < faces[f].size(); ++k, ++t) used.insert(mesh.triangles[t].begin(), mesh.triangles[t].end());
    EXPECT_EQ(used, corners) << what << " face " << f;
  }
}

void expect_brep(const RhinoBrep& brep, const json& expected, const std::string& what) {
  const json& faces = expected["faces"];
  EXPECT_TRUE(brep.skipped_faces.empty()) << what << ": " << brep.skipped_faces.front();
  EXPECT_EQ(brep.edge_count, expected["edge_count"].get<int>()) << what;
  ASSERT_EQ(brep.faces.size(), faces.size()) << what;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const json& face = faces[f];
    const std::string where = what + " face " + std::to_string(f) + " (" + face["surface_class"].get<std::string>() + ")";
    // No generated face is reversed; a reversed one would come back flipped and need another comparison.
    ASSERT_FALSE(face["reversed"].get<bool>()) << where;
    expect_surface(brep.faces[f].surface, face["nurbs_surface"], face["exact"].get<bool>(), where);
    const json& loops = face["loops"];
    ASSERT_EQ(brep.faces[f].loops.size(), loops.size()) << where;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      const auto& loop = brep.faces[f].loops[l];
      const json& trims = loops[l]["trims"];
      ASSERT_EQ(loop.segments.size(), trims.size()) << where << " loop " << l;
      ASSERT_EQ(loop.edges.size(), trims.size()) << where << " loop " << l;
      std::multiset<int> got, want;
      for (std::size_t k = 0; k < trims.size(); ++k) {
        got.insert(loop.edges[k].edge);
        want.insert(trims[k]["edge"].get<int>());
      }
      EXPECT_EQ(got, want) << where << " loop " << l << ": edge indices (-1: singular trim)";
    }
  }
}

// Every group in every archive version rhino3dm 8 writes (File3dmWriteOptions.version 2..8).
const std::vector<std::string> kGroups = {"curves", "surfaces", "breps", "meshes"};
const std::vector<int> kVersions = {2, 3, 4, 50, 60, 70, 80};

std::vector<std::string> all_files() {
  std::vector<std::string> files;
  for (const auto& group : kGroups)
    for (int version : kVersions) files.push_back(group + "_v" + std::to_string(version));
  return files;
}

TEST(Rhino3dmGenerated, IndexListsEveryGroupAndVersion) {
  const json index = load_json(kDir + "/index.json");
  ASSERT_FALSE(index.is_null());
  EXPECT_EQ(index["files"].get<std::vector<std::string>>(), all_files());
  EXPECT_EQ(index["point_style"].get<std::string>(), "homogeneous");
}

class Rhino3dmExact : public ::testing::TestWithParam<std::string> {};

TEST_P(Rhino3dmExact, EveryValueBitEqual) {
  const std::string base = kDir + "/" + GetParam();
  const json expected = load_json(base + ".json");
  ASSERT_FALSE(expected.is_null());
  ASSERT_EQ(expected["point_style"].get<std::string>(), "homogeneous");
  const cadnurbs::rhino::Rhino3dmFile file = cadnurbs::rhino::read_3dm_file(base + ".3dm");

  EXPECT_EQ(file.archive_version, expected["archive_version"].get<int>());
  const std::map<std::string, double> millimetres = {
      {"Millimeters", 1.0}, {"Centimeters", 10.0}, {"Meters", 1000.0}, {"Inches", 25.4}};
  EXPECT_EQ(file.unit.millimetres, millimetres.at(expected["units"]["name"].get<std::string>())) << file.unit.name;

  const json& layers = expected["layers"];
  ASSERT_EQ(file.layers.size(), layers.size());
  for (std::size_t i = 0; i < layers.size(); ++i) {
    EXPECT_EQ(file.layers[i].name, layers[i]["name"].get<std::string>());
    const auto& c = file.layers[i].colour;
    const json& rgb = layers[i]["color"];
    EXPECT_NEAR(c.r, rgb[0].get<double>() / 255.0, 1e-12) << "layer " << i;
    EXPECT_NEAR(c.g, rgb[1].get<double>() / 255.0, 1e-12) << "layer " << i;
    EXPECT_NEAR(c.b, rgb[2].get<double>() / 255.0, 1e-12) << "layer " << i;
  }

  const json& objects = expected["objects"];
  ASSERT_EQ(file.objects.size(), objects.size()) << "warnings: " << file.warnings.size();
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const json& want = objects[k];
    const auto& record = file.objects[k];
    const std::string what = GetParam() + " object " + std::to_string(k) + " '" + want["name"].get<std::string>() +
                             "' (" + want["class"].get<std::string>() + ")";
    EXPECT_EQ(record.class_name, want["class"].get<std::string>()) << what;
    EXPECT_EQ(record.attributes.name, want["name"].get<std::string>()) << what;
    EXPECT_EQ(record.attributes.layer_index, want["layer_index"].get<int>()) << what;
    if (want.contains("nurbs_curve")) {
      const auto* curve = std::get_if<NurbsCurve>(&record.geometry);
      ASSERT_NE(curve, nullptr) << what << " did not come back as a curve";
      expect_curve(*curve, want["nurbs_curve"], want["exact"].get<bool>(), what);
    } else if (want.contains("nurbs_surface")) {
      const auto* surface = std::get_if<NurbsSurface>(&record.geometry);
      ASSERT_NE(surface, nullptr) << what << " did not come back as a surface";
      expect_surface(*surface, want["nurbs_surface"], want["exact"].get<bool>(), what);
    } else if (want.contains("brep")) {
      const auto* brep = std::get_if<RhinoBrep>(&record.geometry);
      ASSERT_NE(brep, nullptr) << what << " did not come back as a Brep";
      expect_brep(*brep, want["brep"], what);
    } else if (want.contains("mesh")) {
      const auto* mesh = std::get_if<TriangleMesh>(&record.geometry);
      ASSERT_NE(mesh, nullptr) << what << " did not come back as a mesh";
      expect_mesh(*mesh, want["mesh"], what);
    } else {
      ADD_FAILURE() << what << ": the JSON holds no values for this class";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllVersions, Rhino3dmExact, ::testing::ValuesIn(all_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
