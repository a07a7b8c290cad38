#pragma once
// Scene-wide numbers for B-rep edges, so that trim segments of different faces lying on the same edge
// carry the same TrimEdgeRef::edge (a watertight tessellation samples each edge once).
// Internal to formats/brep: includes OCCT.
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Edge.hxx>
#include <vector>

namespace cadnurbs {

class EdgeNumbering {
 public:
  // The 0-based number of `edge`, numbering it when first seen. Identity is OCCT's IsSame (the same
  // TEdge at the same location; orientation ignored), so both uses of a seam get one number.
  int number(const TopoDS_Edge& edge);

  // Indexed by number: whether the edge is degenerated (its 3D image is one point).
  const std::vector<bool>& degenerated() const { return degenerated_; }

 private:
  TopTools_IndexedMapOfShape edges_;
  std::vector<bool> degenerated_;
};

}  // namespace cadnurbs
