#pragma once
// An incremental constrained Delaunay triangulation of a trimmed (u,v) domain (CGAL), for
// refinement: loops are constraints, points can be added one by one afterwards, and the triangles
// inside the loops (even-odd) can be listed at any time. Delaunay is taken in scaled coordinates
// (u * scale_u, v * scale_v), so that the caller can make its grid cells roughly square there.
#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

namespace cadnurbs {

class DomainTriangulation {
 public:
  DomainTriangulation(double scale_u, double scale_v);
  ~DomainTriangulation();
  DomainTriangulation(const DomainTriangulation&) = delete;
  DomainTriangulation& operator=(const DomainTriangulation&) = delete;

  // Inserts a point; returns its vertex id (the existing id when the point is already a vertex).
  // `near` (a vertex id, or -1 for the last inserted vertex) is where the point location starts.
  int insert(const Eigen::Vector2d& uv, int near = -1);

  // Constrains the closed polygon through the given vertex ids (consecutive equal ids are skipped).
  // Where it crosses earlier constraints CGAL adds vertices; they get ids too (see uv()).
  void insert_loop(const std::vector<int>& ids);

  // Replaces the constrained edge (a, b) by (a, m), (m, b) with m a new vertex at uv; returns m.
  int split_constrained_edge(int a, int b, const Eigen::Vector2d& uv);

  bool is_constrained(int a, int b) const;

  int vertex_count() const;
  const Eigen::Vector2d& uv(int id) const;

  // Triangles inside an odd number of loops, counter-clockwise in (u,v), as vertex ids.
  std::vector<std::array<int, 3>> inside_triangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cadnurbs
