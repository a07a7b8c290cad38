#include "analysis/tessellation/vertex_classes.hpp"


namespace cadnurbs::tessellation {

namespace {

int slot(CurveEnd end) { return 2 * end.curve.index + (end.side == CurveEndSide::end ? 1 : 0); }

}  // namespace

VertexClasses::VertexClasses(int curve_count)
    : ends_(2 * static_cast<size_t>(curve_count)), node_(2 * static_cast<size_t>(curve_count)) {}

int VertexClasses::root(CurveEnd end) { return ends_.find(slot(end)); }

// The smaller slot stays the root (UnionFind's rule): classes then do not depend on the order of joins.
void VertexClasses::join(CurveEnd a, CurveEnd b) { ends_.unite(slot(a), slot(b)); }

std::optional<NodeId> VertexClasses::node(CurveEnd end) { return node_[root(end)]; }

void VertexClasses::set_node(CurveEnd end, NodeId node) { node_[root(end)] = node; }

}  // namespace cadnurbs::tessellation
