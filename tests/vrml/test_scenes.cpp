#include "test_scenes.hpp"

#include <cmath>

namespace cadnurbs::vrml_test {

namespace {

const double half_sqrt2 = std::sqrt(0.5);

}  // namespace

NurbsSurface quarter_cylinder() {
  NurbsSurface s;
  s.u_order = 3;
  s.v_order = 2;
  s.u_count = 3;
  s.v_count = 2;
  s.u_knots = {0, 0, 0, 1, 1, 1};
  s.v_knots = {0, 0, 1, 1};
  for (double z : {0.0, 20.0}) {
    s.points.emplace_back(10, 0, z);
    s.points.emplace_back(10, 10, z);
    s.points.emplace_back(0, 10, z);
    s.weights.insert(s.weights.end(), {1.0, half_sqrt2, 1.0});
  }
  return s;
}

TrimLoop circle_loop(const Eigen::Vector2d& c, double r) {
  TrimLoop loop;
  const Eigen::Vector2d corners[4] = {{r, 0}, {0, r}, {-r, 0}, {0, -r}};
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d a = corners[k], b = corners[(k + 1) % 4];
    NurbsCurve arc;
    arc.dimension = 2;
    arc.order = 3;
    arc.knots = {0, 0, 0, 1, 1, 1};
    for (const Eigen::Vector2d& p : {a, Eigen::Vector2d(a + b), b}) arc.points.emplace_back(c.x() + p.x(), c.y() + p.y(), 0.0);
    arc.weights = {1.0, half_sqrt2, 1.0};
    loop.segments.emplace_back(arc);
  }
  return loop;
}

TrimmedSurface trimmed_plate() {
  TrimmedSurface t;
  NurbsSurface& s = t.surface;
  s.u_order = s.v_order = 2;
  s.u_count = s.v_count = 2;
  s.u_knots = s.v_knots = {0, 0, 1, 1};
  s.points = {{0, 0, 5}, {100, 0, 5}, {0, 100, 5}, {100, 100, 5}};
  t.loops.push_back(circle_loop({0.5, 0.5}, 0.4));
  Polyline2D hole;
  hole.points = {{0.4, 0.4}, {0.4, 0.6}, {0.6, 0.6}, {0.6, 0.4}, {0.4, 0.4}};  // clockwise
  t.loops.push_back(TrimLoop{{hole}, {}});
  return t;
}

TriangleMesh octahedron_with_normals() {
  TriangleMesh m;
  m.positions = {{7, 0, 0}, {-7, 0, 0}, {0, 7, 0}, {0, -7, 0}, {0, 0, 7}, {0, 0, -7}};
  const int x = 0, nx = 1, y = 2, ny = 3, z = 4, nz = 5;
  m.triangles = {{x, y, z}, {y, nx, z}, {nx, ny, z}, {ny, x, z}, {y, x, nz}, {nx, y, nz}, {ny, nx, nz}, {x, ny, nz}};
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d n =
        (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).normalized();
    for (int k = 0; k < 3; ++k) m.corner_normals.push_back(n);
  }
  return m;
}

NurbsCurve semicircle_curve() {
  NurbsCurve c;
  c.dimension = 3;
  c.order = 3;
  c.knots = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
  c.points = {{5, 0, 1}, {5, 5, 1}, {0, 5, 1}, {-5, 5, 1}, {-5, 0, 1}};
  c.weights = {1, half_sqrt2, 1, half_sqrt2, 1};
  return c;
}

Scene single_shape_scene(Geometry geometry, const std::string& name) {
  Scene scene;
  scene.root.name = "root";
  scene.root.shapes.push_back(Shape{name, std::move(geometry), std::nullopt});
  return scene;
}

Scene assembly_scene(bool with_curve) {
  Scene scene;
  scene.root.name = "Assembly";
  scene.root.colour = Colour{0.2, 0.4, 0.6};

  SceneNode first;
  first.name = "Bracket 1";
  first.transform = Eigen::Translation3d(150, -20, 3) * Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  first.colour = Colour{0.9, 0.1, 0.1};
  first.shapes.push_back(Shape{"wall", TrimmedSurface{quarter_cylinder(), {}}, std::nullopt});
  first.shapes.push_back(Shape{"lid", trimmed_plate(), Colour{0.1, 0.8, 0.3}});
  if (with_curve) first.shapes.push_back(Shape{"edge", semicircle_curve(), std::nullopt});

  SceneNode second;
  second.name = "Bracket 1";
  second.transform = Eigen::Translation3d(-40, 10, 0) * Eigen::AngleAxisd(-1.2, Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::Scaling(1.5, 1.0, 0.5) *
                     Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitZ());
  second.shapes.push_back(Shape{"wall", TrimmedSurface{quarter_cylinder(), {}}, std::nullopt});
  SceneNode grandchild;
  grandchild.name = "Ünïcode mesh";
  grandchild.transform = Eigen::Affine3d(Eigen::Translation3d(0, 0, 30));
  grandchild.shapes.push_back(Shape{"", octahedron_with_normals(), std::nullopt});
  second.children.push_back(grandchild);

  scene.root.children = {first, second};
  return scene;
}

}  // namespace cadnurbs::vrml_test
