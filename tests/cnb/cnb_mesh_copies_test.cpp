// Copies in a mesh group (.cnb format version 5): pieces of a mesh that are another piece turned by a
// signed permutation of the axes and moved on the grid decode as the same oriented triangles, mirrors
// included, and cost a record each instead of a traversal.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <set>

#include "analysis/mesh/oriented_triangle_keys.hpp"
#include "formats/cnb/cnb_mesh_copies.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "tests/cnb/expect_same_mesh_on_grid.hpp"

namespace cadnurbs {
namespace {

// The closed box [low, high], 8 vertices and 12 outward triangles, appended to `mesh`; its face
// `other_diagonal` (0 to 5, or none) cut along its other diagonal.
void add_box(TriangleMesh& mesh, const Eigen::Vector3d& low, const Eigen::Vector3d& high, int other_diagonal = -1) {
  const int first = static_cast<int>(mesh.positions.size());
  for (int i = 0; i < 8; ++i)
    mesh.positions.emplace_back(i & 1 ? high.x() : low.x(), i & 2 ? high.y() : low.y(), i & 4 ? high.z() : low.z());
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int f = 0; f < 6; ++f) {
    const int* q = quads[f];
    if (f == other_diagonal) {
      mesh.triangles.push_back({first + q[0], first + q[1], first + q[3]});
      mesh.triangles.push_back({first + q[1], first + q[2], first + q[3]});
    } else {
      mesh.triangles.push_back({first + q[0], first + q[1], first + q[2]});
      mesh.triangles.push_back({first + q[0], first + q[2], first + q[3]});
    }
  }
}

// An asymmetric wedge (a tetrahedron with four different edge lengths at its first corner) at `at`, or
// its mirror image in x (triangles reversed, so it still faces outwards).
void add_wedge(TriangleMesh& mesh, const Eigen::Vector3d& at, bool mirrored) {
  const int first = static_cast<int>(mesh.positions.size());
  const double s = mirrored ? -1 : 1;
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d(0, 0.5, 0),
                                   Eigen::Vector3d(0.1, 0.1, 0.7)})
    mesh.positions.push_back(at + Eigen::Vector3d(s * p.x(), p.y(), p.z()));
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  for (const auto& f : faces)
    mesh.triangles.push_back(mirrored ? std::array<int, 3>{first + f[0], first + f[2], first + f[1]}
                                      : std::array<int, 3>{first + f[0], first + f[1], first + f[2]});
}

struct Written {
  std::string bytes;
  CnbWriteReport report;
  Scene decoded;
};

Written round_trip(const std::vector<TriangleMesh>& meshes) {
  Scene scene;
  scene.root.name = "part";
  for (size_t k = 0; k < meshes.size(); ++k)
    scene.root.shapes.push_back({"mesh " + std::to_string(k), meshes[k], Colour{0.1 * k, 0.2, 0.3}});
  CnbOptions options;
  options.max_deviation = 0.01;
  options.free_mesh_points = false;  // every vertex where rounding puts it: compared by position
  Written w;
  w.bytes = write_cnb(scene, options, &w.report);
  w.decoded = read_cnb(w.bytes, "copies.cnb");
  return w;
}

// The grid step the writer takes at these options (it depends on D alone here): copies are moves by whole
// steps, so the tests move pieces by whole steps.
double grid_step() {
  TriangleMesh one;
  add_box(one, {0, 0, 0}, {1, 1, 1});
  return round_trip({one}).report.point_step;
}
double on_steps(double x) { return std::round(x / grid_step()) * grid_step(); }

TEST(CnbMeshCopies, TurnsAreThe48SignedPermutations) {
  std::set<cnb::GridPoint> images;
  int mirrors = 0;
  for (int turn = 0; turn < cnb::turn_count; ++turn) {
    images.insert(cnb::turned(turn, {1, 2, 3}));
    Eigen::Matrix3d m;
    for (int k = 0; k < 3; ++k) {
      cnb::GridPoint unit{0, 0, 0};
      unit[k] = 1;
      const cnb::GridPoint image = cnb::turned(turn, unit);
      for (int r = 0; r < 3; ++r) m(r, k) = static_cast<double>(image[r]);
    }
    EXPECT_EQ(cnb::turn_mirrors(turn), m.determinant() < 0) << "turn " << turn;
    mirrors += cnb::turn_mirrors(turn);
  }
  EXPECT_EQ(images.size(), 48u);
  EXPECT_EQ(cnb::turned(0, {1, 2, 3}), (cnb::GridPoint{1, 2, 3}));
  EXPECT_EQ(mirrors, 24);
}

// A body, 24 pads around it (a QFN's: six to a side, each side's pads the first side's turned by a
// quarter turn about z), and two wedges, one the other's mirror image.
std::vector<TriangleMesh> pads_part(bool all_alike) {
  TriangleMesh body, pads, mark;
  add_box(body, {-2, -2, 0.1}, {2, 2, 0.9});
  for (int side = 0; side < 4; ++side)
    for (int i = 0; i < 6; ++i) {
      const double along = -1.25 + on_steps(0.5) * i, length = all_alike ? 0.4 : 0.4 + 0.01 * (6 * side + i);
      TriangleMesh pad;  // from the body's edge outwards by `length`; 0.25 wide, 0.2 high
      add_box(pad, {1.9, along - 0.125, 0}, {1.9 + length, along + 0.125, 0.2});
      for (auto& p : pad.positions)
        for (int turn = 0; turn < side; ++turn) p = Eigen::Vector3d(-p.y(), p.x(), p.z());
      append(pads, pad);
    }
  add_wedge(mark, {-1.5, -1.5, 0.9}, false);
  add_wedge(mark, {1.5, -1.5, 0.9}, true);
  return {body, pads, mark};
}

TEST(CnbMeshCopies, PadsTurnedAndMovedDecodeAsTheSameTriangles) {
  const std::vector<TriangleMesh> meshes = pads_part(true);
  const Written w = round_trip(meshes);
  EXPECT_EQ(w.report.mesh_groups, 1);
  // 23 pads copy the first (the other sides by quarter turns); the mirrored wedge copies the first wedge.
  EXPECT_EQ(w.report.piece_copies, 24);
  ASSERT_EQ(w.decoded.root.shapes.size(), 3u);
  for (size_t k = 0; k < meshes.size(); ++k) {
    SCOPED_TRACE("mesh " + std::to_string(k));
    expect_same_mesh_on_grid(meshes[k], std::get<TriangleMesh>(w.decoded.root.shapes[k].geometry), w.report.point_step);
  }
}

TEST(CnbMeshCopies, ACopyCostsFarLessThanItsTraversal) {
  const Written alike = round_trip(pads_part(true)), unlike = round_trip(pads_part(false));
  EXPECT_EQ(unlike.report.piece_copies, 1);  // only the wedge
  std::cout << "24 pads alike: " << alike.bytes.size() << " bytes; of 24 lengths: " << unlike.bytes.size() << " bytes\n";
  // 23 pads of 8 vertices each: a record of a few bytes against a traversal of 8 vertices.
  EXPECT_LT(2 * alike.bytes.size(), unlike.bytes.size());
}

TEST(CnbMeshCopies, PiecesWithTheSamePointsAreNeverSources) {
  // A wedge, the same wedge inside out (its triangles reversed: the same points, and no turn maps one onto
  // the other), and the wedge moved. The first two cannot be told apart by their points, so the writer
  // codes no copy in that mesh: the moved wedge stays in the traversal.
  TriangleMesh body, marks;
  add_box(body, {-2, -2, 0}, {2, 2, 1});
  add_wedge(marks, {3, 0, 0}, false);
  const size_t first_wedge = marks.triangles.size();
  add_wedge(marks, {3, 0, 0}, false);
  for (size_t t = first_wedge; t < marks.triangles.size(); ++t) std::swap(marks.triangles[t][1], marks.triangles[t][2]);
  add_wedge(marks, {3, on_steps(1), 0}, false);
  const std::vector<TriangleMesh> meshes{body, marks};
  const Written w = round_trip(meshes);
  EXPECT_EQ(w.report.piece_copies, 0);
  for (size_t k = 0; k < meshes.size(); ++k)
    expect_same_mesh_on_grid(meshes[k], std::get<TriangleMesh>(w.decoded.root.shapes[k].geometry), w.report.point_step);
  // Without the inside-out wedge, the moved one is a copy.
  TriangleMesh two = marks;
  two.triangles.erase(two.triangles.begin() + static_cast<long>(first_wedge), two.triangles.begin() + static_cast<long>(2 * first_wedge));
  const Written without = round_trip({body, two});
  EXPECT_EQ(without.report.piece_copies, 1) << "step " << without.report.point_step;
}

TEST(CnbMeshCopies, AFlatFaceCutAlongTheOtherDiagonalIsStillACopy) {
  TriangleMesh body, pads;
  add_box(body, {-2, -2, 0}, {2, 2, 1});
  add_box(pads, {3, 0, 0}, {3.5, 0.25, 0.2});
  add_box(pads, {3, on_steps(1), 0}, {3.5, on_steps(1) + 0.25, 0.2}, 2);
  const Written w = round_trip({body, pads});
  EXPECT_EQ(w.report.piece_copies, 1);
  const auto& decoded = std::get<TriangleMesh>(w.decoded.root.shapes[1].geometry);
  ASSERT_EQ(decoded.triangles.size(), pads.triangles.size());
  EXPECT_EQ(decoded.positions.size(), pads.positions.size());
  // The copy takes its source's diagonal: the same vertices and surface, not the same triangles.
  const TriangleMesh on_grid = mesh_on_grid(pads, w.report.point_step);
  EXPECT_NEAR(mesh_area(decoded), mesh_area(on_grid), 1e-12);
  EXPECT_NE(oriented_triangle_keys(decoded.positions, decoded.triangles),
            oriented_triangle_keys(on_grid.positions, on_grid.triangles));
}

TEST(CnbMeshCopies, ABentQuadCutAlongTheOtherDiagonalIsNot) {
  // Four points not in one plane: the two diagonals make different surfaces.
  TriangleMesh body, tents;
  add_box(body, {-2, -2, 0}, {2, 2, 1});
  for (int copy = 0; copy < 2; ++copy) {
    const int first = static_cast<int>(tents.positions.size());
    const double x = 3 + copy * on_steps(2);
    for (const Eigen::Vector3d& p : {Eigen::Vector3d(x, 0, 0), Eigen::Vector3d(x + 1, 0, 0),
                                     Eigen::Vector3d(x + 1, 1, 0.3), Eigen::Vector3d(x, 1, 0)})
      tents.positions.push_back(p);
    if (copy == 0)
      tents.triangles.insert(tents.triangles.end(), {{first, first + 1, first + 2}, {first, first + 2, first + 3}});
    else
      tents.triangles.insert(tents.triangles.end(), {{first, first + 1, first + 3}, {first + 1, first + 2, first + 3}});
  }
  const Written w = round_trip({body, tents});
  EXPECT_EQ(w.report.piece_copies, 0);
  expect_same_mesh_on_grid(tents, std::get<TriangleMesh>(w.decoded.root.shapes[1].geometry), w.report.point_step);
}

}  // namespace
}  // namespace cadnurbs
