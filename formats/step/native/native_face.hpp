#pragma once
// One STEP face as a trimmed NURBS surface, its trimming curves computed from the edges' 3D curves (library
// STEP files carry no pcurves). Internal to formats/step/native.
//
// How each edge use gets its curve in (u, v):
// - on a plane, exactly: the edge's NURBS mapped by the plane's affine chart (control points projected,
//   weights and knots kept); likewise on a bilinear B-spline patch whose net is a parallelogram (an
//   affine map of its plane);
// - on the other surfaces the edge is sampled and each sample located on the surface (closed forms on the
//   analytic surfaces, Newton on B-splines), continuing from the previous sample so that angles unwrap
//   across seams; an edge whose samples keep one parameter (a ruling, a parallel, a meridian, a B-spline's
//   iso-curve) becomes the exact straight segment between its ends, any other is fitted
//   (core/fit_trim_curve) within `fit_tolerance` of the edge's projection onto the surface, checked at
//   samples (within a hundredth of the edge's distance from the surface where that is larger: files keep
//   edges within a tolerance of their faces, not on them);
// - a closed profile's parameter (an extruded or revolved whole circle) is periodic like an angle: loops
//   unwrap across the profile's start and are then moved into its range;
// - a use that starts or ends at a pole (sphere, cone apex) takes the angle of its next sample; the gap
//   this leaves between uses is bridged by a straight segment at the pole (one point in 3D).
// An analytic surface becomes its exact NURBS over the face's box (core/analytic_surface): angles as far as
// the loops reach (at most one turn), other parameters as far as the trimming curves' control points.
// A face whose same_sense is false is mirrored in u, so that Su x Sv points out of the material; loops are
// then oriented (outer counter-clockwise).
// Refuses (GeometryError, reason only): a loop that wraps around a periodic surface without closing
// (a face bounded by whole circles and no seam edge), a face spanning more than one turn, an edge that does
// not lie on the surface within `fit_tolerance` or cannot be fitted, gaps between uses that are not one
// point in 3D.
#include <vector>

#include "core/trimmed_surface.hpp"
#include "formats/step/native/step_topology.hpp"

namespace cadnurbs::step {

// The diagonal of the box of the face's edges' control points (0 for a face without edges): the face's size.
double face_size(const StepFace& face, const std::vector<StepEdge>& edges);

// `fit_tolerance`: in millimetres, the largest distance of a fitted trimming curve's image from its edge.
TrimmedSurface native_face(const StepFace& face, const std::vector<StepEdge>& edges, double fit_tolerance);

}  // namespace cadnurbs::step
