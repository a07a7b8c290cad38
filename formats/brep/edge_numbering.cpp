#include "formats/brep/edge_numbering.hpp"

#include <BRep_Tool.hxx>

namespace cadnurbs {

int EdgeNumbering::number(const TopoDS_Edge& edge) {
  const int index = edges_.Add(edge);  // 1-based; the existing index when already present
  if (index > static_cast<int>(degenerated_.size())) degenerated_.push_back(BRep_Tool::Degenerated(edge));
  return index - 1;
}

}  // namespace cadnurbs
