#include "analysis/tessellation/vertex_classes.hpp"

#include <algorithm>
#include <numeric>

namespace cadnurbs::tessellation {

namespace {

int slot(CurveEnd end) { return 2 * end.curve.index + (end.side == CurveEndSide::end ? 1 : 0); }

}  // namespace

VertexClasses::VertexClasses(int curve_count) : parent_(2 * static_cast<size_t>(curve_count)), node_(parent_.size()) {
  std::iota(parent_.begin(), parent_.end(), 0);
}

int VertexClasses::root(CurveEnd end) {
  int x = slot(end);
  while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
  return x;
}

void VertexClasses::join(CurveEnd a, CurveEnd b) {
  const int ra = root(a), rb = root(b);
  // The smaller slot stays the root: classes then do not depend on the order of joins.
  if (ra != rb) parent_[std::max(ra, rb)] = std::min(ra, rb);
}

std::optional<NodeId> VertexClasses::node(CurveEnd end) { return node_[root(end)]; }

void VertexClasses::set_node(CurveEnd end, NodeId node) { node_[root(end)] = node; }

}  // namespace cadnurbs::tessellation
