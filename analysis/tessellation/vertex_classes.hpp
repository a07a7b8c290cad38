#pragma once
// Which model curve ends are one model vertex (internal): ends are joined where one segment of a loop
// ends and the next starts, and at both ends of a collapsed curve; each class then gets one node.
// A union-find over the 2 ends of every curve.
#include <optional>
#include <vector>

#include "analysis/tessellation/tessellation_ids.hpp"
#include "core/union_find.hpp"

namespace cadnurbs::tessellation {

class VertexClasses {
 public:
  // Every end of curves 0 .. curve_count - 1 in a class of its own, without a node.
  explicit VertexClasses(int curve_count);

  // One class from the classes of a and b.
  void join(CurveEnd a, CurveEnd b);

  // The node of end's class, once set_node gave it one.
  std::optional<NodeId> node(CurveEnd end);
  void set_node(CurveEnd end, NodeId node);

 private:
  UnionFind ends_;                           // by end slot (2 per curve: start, end)
  std::vector<std::optional<NodeId>> node_;  // by class root
  int root(CurveEnd end);
};

}  // namespace cadnurbs::tessellation
