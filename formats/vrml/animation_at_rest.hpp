#pragma once
// The coordinates an animation gives a scene when it is loaded. A CoordinateInterpolator whose
// set_fraction a looping TimeSensor drives (loop TRUE: it runs from the moment the file is loaded) sets
// the points it is routed to (a NurbsSurface's controlPoint, a Coordinate's point, by ROUTE ...
// value_changed TO ... set_controlPoint / set_point / controlPoint / point) on every frame; a viewer never
// shows the values the file writes there. At rest is the animation's first frame, fraction 0: the
// interpolator's first keyValue set. (white_dune's fish.wrl writes 1075711066505216 as a control point
// its animation always replaces.) Interpolators that a sensor or a Script starts, and every other kind
// of interpolator, leave the fields as the file writes them.
#include <string>
#include <vector>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// Sets the routed fields of `document`'s nodes to their values at rest. Returns one note per kind of
// field set, "<count> <Interpolator> routed to <field>: taken at the first key of its looping
// animation (fraction 0)". An interpolator whose keyValue does not hold a whole set per key, or whose
// set is not the size of the field it replaces, leaves the field alone.
std::vector<std::string> apply_animation_at_rest(NodeDocument& document);

}  // namespace cadnurbs
