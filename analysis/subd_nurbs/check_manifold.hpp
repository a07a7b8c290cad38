#pragma once
// Checks a SubD control net before it is refined (internal to analysis/subd_nurbs): what validate() checks,
// then that every edge has at most two faces and two faces run a shared edge opposite ways, which
// Catmull-Clark (ours and OpenSubdiv's) needs. Throws GeometryError(entity, reason) naming the edge.
#include <string>

#include "core/subd_control_net.hpp"

namespace cadnurbs::subd_nurbs {

void check_manifold(const SubdControlNet& net, const std::string& entity);

}  // namespace cadnurbs::subd_nurbs
