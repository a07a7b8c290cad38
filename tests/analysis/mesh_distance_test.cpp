// mesh_distance's RMS is a surface integral: a sheet whose halves are meshed very unevenly measures
// the closed form, where pooling the samples by count would follow the finely meshed half.
#include "analysis/measure/mesh_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/mesh/sample_triangles.hpp"

namespace cadnurbs {
namespace {

// The rectangle [0,2] x [0,1] in z = 0: [0,1] x [0,1] as two triangles, [1,2] x [0,1] as a 16 x 16
// grid of squares, two triangles each (the halves share only the corners (1,0) and (1,1)).
TriangleMesh unevenly_meshed_sheet() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  const int n = 16, base = 4;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({1.0 + double(i) / n, double(j) / n, 0});
  const auto at = [&](int i, int j) { return base + j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// The plane z = x over [-1, 3] x [-1, 2]: a point (x, y, 0) of the sheet is x / sqrt(2) from it, its
// nearest point (x/2, y, x/2) inside.
TriangleMesh tilted_plane() {
  TriangleMesh m;
  m.positions = {{-1, -1, -1}, {3, -1, 3}, {3, 2, 3}, {-1, 2, -1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(SampleTriangles, AreaWeightsSumToTheMeshArea) {
  std::vector<double> weights;
  const auto points = sample_triangles(unevenly_meshed_sheet(), 1.0, &weights);
  ASSERT_EQ(weights.size(), points.size());
  double sum = 0;
  for (double w : weights) sum += w;
  EXPECT_NEAR(sum, 2.0, 1e-12);
}

TEST(MeshDistance, RmsIsTheSurfaceIntegralHoweverUnevenTheMesh) {
  // mean of d^2 = (1/2) * integral_0^2 x^2 / 2 dx = 2/3. Pooled by count (7 samples on each of the
  // 2 large and 512 small triangles, plus the vertices), the [1,2] half would weigh some 40 times
  // as much as the [0,1] half and give about sqrt(7/6) = 1.08.
  const MeshDistance d = mesh_distance(unevenly_meshed_sheet(), tilted_plane(), 1.0);
  EXPECT_NEAR(d.a_to_b.rms, std::sqrt(2.0 / 3.0), 0.015);  // measured 0.825: the lattice quadrature
  EXPECT_NEAR(d.a_to_b.max, 2.0 / std::sqrt(2.0), 1e-9);
}

}  // namespace
}  // namespace cadnurbs
