#pragma once
// Test helper shared by the STEP/IGES and .3dm corpus tests: whether a scene node's faces form a closed
// solid by their edge numbers.
#include <map>
#include <utility>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs::test {

// True when every edge the node's trimmed faces name is used exactly twice, once each way. Edges < 0 (no
// shared edge) and those marked in `degenerated` (indexed by edge; shorter or empty: none) are skipped.
// False for a node with no named edge or with a shape that is not a trimmed surface.
inline bool closed_solid(const SceneNode& node, const std::vector<bool>& degenerated = {}) {
  std::map<int, std::pair<int, int>> uses;  // edge -> (uses, uses against its direction)
  for (const auto& shape : node.shapes) {
    const auto* t = std::get_if<TrimmedSurface>(&shape.geometry);
    if (!t) return false;
    for (const auto& loop : t->loops)
      for (const auto& ref : loop.edges) {
        if (ref.edge < 0 || (ref.edge < static_cast<int>(degenerated.size()) && degenerated[ref.edge])) continue;
        ++uses[ref.edge].first;
        if (ref.reversed) ++uses[ref.edge].second;
      }
  }
  if (uses.empty()) return false;
  for (const auto& [edge, count] : uses)
    if (count.first != 2 || count.second != 1) return false;
  return true;
}

}  // namespace cadnurbs::test
