#pragma once
// The model vertices of a tessellation (internal; see NodeId): one 3D point each, stored in the frame
// of the face that made it, so that every face using a node gets the same bits when its frame is the
// same (and the point moved through the world transforms when a solid is placed again).
#include <Eigen/Geometry>
#include <vector>

#include "analysis/tessellation/tessellation_face.hpp"
#include "analysis/tessellation/tessellation_ids.hpp"

namespace cadnurbs::tessellation {

class ModelNodes {
 public:
  // `faces` supplies the frames (Face::world); it must outlive this table.
  explicit ModelNodes(const std::vector<Face>& faces) : faces_(faces) {}

  // A new node at `point`, given in the frame of face `face`.
  NodeId add(const Eigen::Vector3d& point, int face);

  // The node's point in the frame of face `face`: the stored bits when the frames are equal.
  Eigen::Vector3d in_frame_of(NodeId node, int face) const;

 private:
  const std::vector<Face>& faces_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<int> faces_of_points_;  // the face whose frame points_ is in
};

}  // namespace cadnurbs::tessellation
