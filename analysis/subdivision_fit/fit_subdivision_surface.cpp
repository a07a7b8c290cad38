#include "analysis/subdivision_fit/fit_subdivision_surface.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "analysis/subdivision_fit/triangle_projection.hpp"
#include "analysis/subdivision/limit_surface.hpp"

namespace cadnurbs {

namespace {

using namespace subdivision_fit;  // the closest-point helpers shared with improve_control_connectivity
using Triplet = Eigen::Triplet<double>;
using Sparse = Eigen::SparseMatrix<double>;

std::vector<K::Triangle_3> cgal_triangles(const TriangleMesh& mesh) {
  std::vector<K::Triangle_3> out;
  out.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    out.emplace_back(cg(mesh.positions[t[0]]), cg(mesh.positions[t[1]]), cg(mesh.positions[t[2]]));
  return out;
}

struct Samples {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;  // unit, or zero where the input has no area
  std::vector<int> owner;                // the input vertex nearest the point (of its triangle's corners)
  std::vector<double> area;              // the input area the point stands for (they sum to the input's)
};

// The data points: every input vertex (area-weighted normal), and on every triangle the points of a
// lattice at most half the mean edge length apart (its centroid at least), with the face normal.
// Vertices and centroids alone leave long triangles unwatched: the fit could bulge inside them.
Samples data_samples(const TriangleMesh& input) {
  Samples s;
  s.points = input.positions;
  s.normals.assign(input.positions.size(), Eigen::Vector3d::Zero());
  s.area.assign(input.positions.size(), 0.0);
  for (size_t v = 0; v < input.positions.size(); ++v) s.owner.push_back(static_cast<int>(v));
  double edge_sum = 0;
  for (const auto& t : input.triangles)
    for (int k = 0; k < 3; ++k) edge_sum += (input.positions[t[k]] - input.positions[t[(k + 1) % 3]]).norm();
  const double spacing = edge_sum / (3.0 * static_cast<double>(input.triangles.size())) / 2;
  for (const auto& t : input.triangles) {
    const Eigen::Vector3d& a = input.positions[t[0]];
    const Eigen::Vector3d& b = input.positions[t[1]];
    const Eigen::Vector3d& c = input.positions[t[2]];
    const Eigen::Vector3d area_normal = (b - a).cross(c - a);
    for (const int v : t) s.normals[v] += area_normal;
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int n = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, 16);
    const Eigen::Vector3d unit = area_normal.norm() > 0 ? Eigen::Vector3d(area_normal.normalized()) : Eigen::Vector3d::Zero();
    const size_t first_own = s.points.size();
    auto add = [&](const Eigen::Vector3d& p) {
      s.points.push_back(p);
      s.normals.push_back(unit);
      int nearest = 0;
      for (int k = 1; k < 3; ++k)
        if ((input.positions[t[k]] - p).squaredNorm() < (input.positions[t[nearest]] - p).squaredNorm()) nearest = k;
      s.owner.push_back(t[nearest]);
    };
    if (n < 3) add((a + b + c) / 3);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const int k = n - i - j;
        if (i == n || j == n || k == n || n < 3) continue;  // corners are the vertices
        add((i * a + j * b + k * c) / n);
      }
    const double share = 0.5 * area_normal.norm() / static_cast<double>(s.points.size() - first_own + 3);
    s.area.resize(s.points.size(), share);
    for (const int v : t) s.area[v] += share;
  }
  for (size_t v = 0; v < input.positions.size(); ++v)
    if (s.normals[v].norm() > 0) s.normals[v].normalize();
  return s;
}

// Vertex normals of a mesh (area-weighted, unit or zero).
std::vector<Eigen::Vector3d> vertex_normals(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> normals(mesh.positions.size(), Eigen::Vector3d::Zero());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d n = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
    for (const int v : t) normals[v] += n;
  }
  for (auto& n : normals)
    if (n.norm() > 0) n.normalize();
  return normals;
}

// The limit mesh's area each of its first `count` vertices (the coarser level's) stands for: a third of
// its triangles' area, scaled so that they sum to the mesh's area (the finer vertices are not samples).
std::vector<double> coarse_vertex_areas(const TriangleMesh& surface, int count) {
  std::vector<double> area(surface.positions.size(), 0.0);
  double total = 0;
  for (const auto& t : surface.triangles) {
    const double a = 0.5 * (surface.positions[t[1]] - surface.positions[t[0]]).cross(surface.positions[t[2]] - surface.positions[t[0]]).norm();
    total += a;
    for (const int v : t) area[v] += a / 3;
  }
  area.resize(static_cast<size_t>(count));
  double coarse = 0;
  for (const double a : area) coarse += a;
  if (coarse > 0)
    for (double& a : area) a *= total / coarse;
  return area;
}

// A point and the surface point found for it face opposite ways: on a thin wall the nearest point
// can be on the other side, and fitting to it would fold the surface. Such pairs are measured but
// not fitted (the usual normal-compatibility test of closest-point fitting).
bool facing_away(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a.dot(b) < 0; }

// The direction a residual is measured along: the surface normal at the foot point, unless the offset
// is longer than `far` and turns from it so far that the foot is on a rim or a crease and the target
// beside the surface, not above it (SubdivisionFitOptions::off_normal_cosine); then the offset itself.
Eigen::Vector3d residual_direction(const Eigen::Vector3d& normal, const Eigen::Vector3d& offset,
                                   double off_normal_cosine, double far) {
  const double length = offset.norm();
  if (length > far && std::abs(normal.dot(offset)) < off_normal_cosine * length) return offset / length;
  return normal;
}

// One round's residuals, as distances.
struct Residuals {
  std::vector<double> data_to_surface;      // per data point
  std::vector<double> surface_to_data;      // per limit vertex
  std::vector<int> surface_owner;           // the input vertex nearest each limit vertex's foot
  double rms = 0, max = 0;
};

// Spring energy sum over control edges |x_a - x_b|^2, as a matrix over the unknowns (x, y, z of each
// control point in turn), built once per connectivity.
Sparse spring_matrix(const SubdivisionControlMesh& control) {
  std::set<std::array<int, 2>> edges;
  for (const auto& t : control.triangles)
    for (int k = 0; k < 3; ++k) edges.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  std::vector<Triplet> w;
  for (const auto& [a, b] : edges)
    for (int axis = 0; axis < 3; ++axis) {
      w.emplace_back(3 * a + axis, 3 * a + axis, 1.0);
      w.emplace_back(3 * b + axis, 3 * b + axis, 1.0);
      w.emplace_back(3 * a + axis, 3 * b + axis, -1.0);
      w.emplace_back(3 * b + axis, 3 * a + axis, -1.0);
    }
  const long n = 3 * static_cast<long>(control.positions.size());
  Sparse out(n, n);
  out.setFromTriplets(w.begin(), w.end());
  return out;
}

// One fitted point: its stencil over the control points (duplicates merged), where it should be, and
// the normal of the surface it is measured against.
struct Correspondence {
  std::vector<std::pair<int, double>> stencil;
  Eigen::Vector3d target, normal;
  double weight = 1;
};

std::vector<std::pair<int, double>> merged(std::vector<std::pair<int, double>> entries) {
  std::sort(entries.begin(), entries.end());
  std::vector<std::pair<int, double>> out;
  for (const auto& e : entries) {
    if (!out.empty() && out.back().first == e.first) out.back().second += e.second;
    else out.push_back(e);
  }
  return out;
}

// Solves for the control points that minimise, over the correspondences, the squared distance to
// each target's tangent plane plus `tangent_weight` times the squared distance to the target itself
// (squared distance minimisation: Pottmann & Leopoldseder 2003, as Ma et al. 2004 fit Loop surfaces;
// the plane term lets the surface slide along the data, which point-to-point fitting does only
// slowly), plus the spring term. Returns false when the system is singular.
bool solve_control_points(const std::vector<Correspondence>& pairs, const Sparse& springs, double spring_weight,
                          double tangent_weight, std::vector<Eigen::Vector3d>& positions) {
  const long nc = static_cast<long>(positions.size());
  std::vector<Triplet> j;
  std::vector<double> b;
  const double root = std::sqrt(tangent_weight);
  for (const Correspondence& c : pairs) {
    const long plane_row = static_cast<long>(b.size());
    const double s = std::sqrt(c.weight);
    for (const auto& [col, w] : c.stencil)
      for (int k = 0; k < 3; ++k) {
        if (c.normal[k] != 0) j.emplace_back(plane_row, 3L * col + k, s * w * c.normal[k]);
        j.emplace_back(plane_row + 1 + k, 3L * col + k, s * root * w);
      }
    b.push_back(s * c.normal.dot(c.target));
    for (int k = 0; k < 3; ++k) b.push_back(s * root * c.target[k]);
  }
  Sparse jm(static_cast<long>(b.size()), 3 * nc);
  jm.setFromTriplets(j.begin(), j.end());
  const Sparse jt = jm.transpose();
  Eigen::SimplicialLDLT<Sparse> solver(Sparse(jt * jm + spring_weight * springs));
  if (solver.info() != Eigen::Success) return false;
  const Eigen::VectorXd x = solver.solve(jt * Eigen::Map<const Eigen::VectorXd>(b.data(), static_cast<long>(b.size())));
  if (solver.info() != Eigen::Success || !x.allFinite()) return false;
  for (long c = 0; c < nc; ++c) positions[c] = x.segment<3>(3 * c);
  return true;
}

// Fits the positions of `control` (connectivity fixed); returns the residuals of the best round.
Residuals fit_positions(const std::vector<K::Triangle_3>& input_triangles,
                        const std::vector<std::array<int, 3>>& input_mesh_triangles, const TriangleTree& input_tree,
                        const Samples& data, SubdivisionControlMesh& control, const SubdivisionFitOptions& options,
                        int max_iterations, SubdivisionFitReport& report) {
  const SubdivisionLimitMesh limit = subdivision_limit_mesh(control_mesh_topology(control), options.levels);
  const LimitStencils& rows = limit.limit_from_control;
  const Sparse springs = spring_matrix(control);
  auto stencil_of = [&](int vertex, double weight, std::vector<std::pair<int, double>>& out) {
    for (LimitStencils::InnerIterator it(rows, vertex); it; ++it) out.emplace_back(static_cast<int>(it.col()), weight * it.value());
  };

  // balance_sides' unit: the mean input area a data point stands for, so the weights average 1 and
  // the spring weight keeps its meaning.
  const bool balance = options.balance_sides;
  double data_area_each = 0;
  for (const double a : data.area) data_area_each += a;
  data_area_each /= static_cast<double>(data.points.size());

  Residuals best;
  best.rms = INFINITY;
  int stale = 0;
  std::vector<Eigen::Vector3d> best_positions = control.positions;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    const TriangleMesh surface = evaluate_limit_mesh(limit, control.positions);
    const std::vector<K::Triangle_3> triangles = cgal_triangles(surface);
    TriangleTree tree(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();

    Residuals r;
    r.data_to_surface.resize(data.points.size());
    r.surface_to_data.resize(static_cast<size_t>(limit.coarser_vertex_count));
    r.surface_owner.resize(static_cast<size_t>(limit.coarser_vertex_count));
    std::vector<Correspondence> pairs;
    pairs.reserve(data.points.size() + surface.positions.size());
    // Only residuals far beyond the best round's RMS turn to their offsets: near the surface the
    // offsets of noise and of the limit mesh's facets point anywhere, and fitting along them slows the
    // sliding (on a noisy vessel every residual turned: 3 to 4 times the rounds).
    const double far = options.off_normal_rms_share * best.rms;
    double weighted_sum = 0, weight_total = 0;  // squared distances and weights, both sides
    for (size_t i = 0; i < data.points.size(); ++i) {
      const auto [point, primitive] = tree.closest_point_and_primitive(cg(data.points[i]));
      const int t = static_cast<int>(primitive - triangles.begin());
      const auto& tri = surface.triangles[t];
      const auto& p = surface.positions;
      const Eigen::Vector3d bary = barycentric(eig(point), p[tri[0]], p[tri[1]], p[tri[2]]);
      Correspondence c;
      for (int k = 0; k < 3; ++k) stencil_of(tri[k], bary[k], c.stencil);
      c.stencil = merged(std::move(c.stencil));
      c.target = data.points[i];
      c.normal = unit_normal(p[tri[0]], p[tri[1]], p[tri[2]]);
      if (balance) c.weight = data.area[i] / data_area_each;
      const double d = (eig(point) - data.points[i]).norm();
      weighted_sum += c.weight * d * d;
      weight_total += c.weight;
      const bool away = facing_away(c.normal, data.normals[i]);
      c.normal = residual_direction(c.normal, c.target - eig(point), options.off_normal_cosine, far);
      if (!away) pairs.push_back(std::move(c));
      r.data_to_surface[i] = d;
      r.max = std::max(r.max, d);
    }
    const std::vector<Eigen::Vector3d> surface_normals = vertex_normals(surface);
    const std::vector<double> surface_area =
        balance ? coarse_vertex_areas(surface, limit.coarser_vertex_count) : std::vector<double>{};
    // The surface's side: the limit points of level k-1's vertices (a quarter of level k's: enough
    // to watch the surface between data points, and the solve's cost grows with the samples).
    const size_t surface_samples = static_cast<size_t>(limit.coarser_vertex_count);
    for (size_t v = 0; v < surface_samples; ++v) {
      const auto [point, primitive] = input_tree.closest_point_and_primitive(cg(surface.positions[v]));
      const K::Triangle_3& face = *primitive;
      const size_t face_index = static_cast<size_t>(primitive - input_triangles.begin());
      int nearest = 0;
      for (int k = 1; k < 3; ++k)
        if (CGAL::squared_distance(face[k], point) < CGAL::squared_distance(face[nearest], point)) nearest = k;
      r.surface_owner[v] = input_mesh_triangles[face_index][nearest];
      Correspondence c;
      stencil_of(static_cast<int>(v), 1.0, c.stencil);
      c.target = eig(point);
      c.normal = unit_normal(eig(face[0]), eig(face[1]), eig(face[2]));
      if (balance) c.weight = surface_area[v] / data_area_each;
      const double d = (eig(point) - surface.positions[v]).norm();
      weighted_sum += c.weight * d * d;
      weight_total += c.weight;
      const bool away = facing_away(c.normal, surface_normals[v]);
      c.normal = residual_direction(c.normal, c.target - surface.positions[v], options.off_normal_cosine, far);
      if (options.fit_limit_points_facing_away || !away) pairs.push_back(std::move(c));
      r.surface_to_data[v] = d;
      r.max = std::max(r.max, d);
    }
    r.rms = std::sqrt(weighted_sum / weight_total);
    // Stop after three rounds without a gain of 0.1 %; keep the best state seen.
    if (r.rms < (1 - 1e-3) * best.rms) stale = 0;
    else if (++stale >= 3) break;
    if (r.rms < best.rms) {
      best = r;
      best_positions = control.positions;
    }
    // Relative to the data: pairs per (vertices + 2 edges) / 4, the entries of one axis' spring matrix.
    const double spring_weight =
        options.fairness * static_cast<double>(pairs.size()) / std::max<long>(1, springs.nonZeros() / 12);
    if (!solve_control_points(pairs, springs, spring_weight, options.tangent_weight, control.positions)) break;
    ++report.iterations;
  }
  control.positions = best_positions;
  return best;
}

}  // namespace

SubdivisionControlMesh fit_subdivision_surface(const TriangleMesh& input, const SubdivisionControlMesh& start, const SubdivisionFitOptions& options,
                                 SubdivisionFitReport* report) {
  if (input.triangles.empty()) throw std::invalid_argument("fit_subdivision_surface: the input has no triangles");
  if (start.triangles.empty()) throw std::invalid_argument("fit_subdivision_surface: the control mesh has no triangles");
  if (options.levels < 1 || options.levels > 5) throw std::invalid_argument("fit_subdivision_surface: levels must be 1 to 5");
  const std::vector<K::Triangle_3> input_triangles = cgal_triangles(input);
  TriangleTree input_tree(input_triangles.begin(), input_triangles.end());
  input_tree.accelerate_distance_queries();
  const Samples data = data_samples(input);

  SubdivisionFitReport r;
  r.data_samples = static_cast<long>(data.points.size());
  SubdivisionControlMesh control = start;
  const Residuals residuals =
      fit_positions(input_triangles, input.triangles, input_tree, data, control, options, options.max_iterations, r);
  r.rms = residuals.rms;
  r.max = residuals.max;
  r.input_vertex_distance.assign(input.positions.size(), 0.0);
  for (size_t i = 0; i < data.points.size(); ++i) {
    double& d = r.input_vertex_distance[data.owner[i]];
    d = std::max(d, residuals.data_to_surface[i]);
  }
  for (size_t v = 0; v < residuals.surface_to_data.size(); ++v) {
    double& d = r.input_vertex_distance[residuals.surface_owner[v]];
    d = std::max(d, residuals.surface_to_data[v]);
  }
  if (report) *report = r;
  return control;
}

}  // namespace cadnurbs
