#pragma once
// Pcurves put on the same sheet of a closed surface's parameterization as their wire. Internal to
// formats/brep: includes OCCT.
#include <Geom_BSplineSurface.hxx>
#include <vector>

#include "formats/brep/face_pcurves.hpp"

namespace cadnurbs {

// Takes a B-spline surface and the face's wires on it. In each direction where the surface is periodic or
// closed (its first and last rows of poles coincide: period = the domain's length), a pcurve that starts
// a whole number of periods (within 1e-3 of one) from where the one before it in the wire ends is moved
// by those periods, when its start and that end are one 3D point within the joint's tolerance and the
// gap is not itself one 3D point (a pole, which close_wire bridges). Each wire's first pcurve stays.
// L_CommonMode_Toroid_Vertical_L19.3mm...'s 1.7e-4 mm^2 sliver on a cylinder has a 0.01 mm edge by the
// seam whose source pcurve jumps a period between two poles (u = 2 pi, then 0); NurbsConvert re-projects
// it whole at u = 2 pi - 0.0005 .. 2 pi, while its neighbours meet it at -0.0005 and 0.
// Returns how many pcurves moved.
int align_pcurves(const Handle(Geom_BSplineSurface)& surface, std::vector<WireUses>& wires);

}  // namespace cadnurbs
