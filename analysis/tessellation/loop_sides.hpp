#pragma once
// Which constrained edges of a CGAL constrained triangulation bound the region between trimming loops
// (even-odd). Loops are inserted as constraints side by side; where two loop sides run along the same
// edge (a hole that shares a tiny side with its outer loop, as KiCad's LED domes do), CGAL keeps one
// constraint, yet even-odd that edge bounds nothing: crossing it must keep the nesting level. Used by
// the tessellator's flood fill (domain_triangulation), whose loops move as refinement splits their
// sides; triangulate_polygon, whose loops are fixed, decides each region with core/point_in_loops
// instead, the test the area and deviation measures share. Header-only: templated on the
// triangulation type, whose vertex handles key the count.
#include <map>
#include <utility>

namespace cadnurbs {

template <class Cdt>
class LoopSides {
 public:
  using Vertex = typename Cdt::Vertex_handle;

  // One loop side from a to b (either direction) was inserted as a constraint.
  void add(Vertex a, Vertex b) { ++count_[key(a, b)]; }

  // The constraint a-b was replaced by a-m and m-b: they carry its count.
  void split(Vertex a, Vertex b, Vertex m) {
    const auto it = count_.find(key(a, b));
    if (it == count_.end()) return;
    const int n = it->second;
    count_.erase(it);
    count_[key(a, m)] = count_[key(m, b)] = n;
  }

  // Whether crossing edge i of face f goes one nesting level deeper: it is constrained and an odd
  // number of loop sides run along it (an edge CGAL split where loops cross counts as one side).
  bool bounds(const Cdt& cdt, typename Cdt::Face_handle f, int i) const {
    if (!cdt.is_constrained({f, i})) return false;
    const auto it = count_.find(key(f->vertex(Cdt::cw(i)), f->vertex(Cdt::ccw(i))));
    return it == count_.end() || it->second % 2 == 1;
  }

 private:
  static std::pair<Vertex, Vertex> key(Vertex a, Vertex b) { return b < a ? std::pair{b, a} : std::pair{a, b}; }
  std::map<std::pair<Vertex, Vertex>, int> count_;
};

}  // namespace cadnurbs
