#pragma once
// Display hints for viewers that tessellate NURBS uniformly (X3D/VRML uTessellation, vTessellation,
// NurbsCurve2D tessellation): counts with which such a viewer draws a face within about `deviation`
// (model units) of the exact surface. Zero means: the viewer's default is already fine (or the entity
// needs no hint, e.g. degree 1, or a polyline).
//
// What the viewers do with the counts (read in their sources: X_ITE 15.0.1 dist/assets/components/
// NURBSComponent.js, Castle Game Engine 7.0-alpha.2 as in view3dscene 4.2, castlenurbs.pas and
// x3dnodes_standard_nurbs.inc; the same for X3D NurbsPatchSurface / NurbsTrimmedSurface and VRML97
// NurbsSurface):
//   n = value                 if value > 0,
//       -value * dimension    if value < 0   (dimension: control points in that direction),
//       2 * dimension         if value = 0;
//   then n segments (n + 1 sample values) uniform in the parameter over the whole domain, knots
//   ignored: u_i = a + (b - a) i / n. X_ITE takes [a, b] = [knot[order-1], knot[dimension]],
//   view3dscene [first knot, last knot] (the same for clamped knots, which cadnurbs writes).
//   X_ITE multiplies n by NurbsSet.tessellationScale (floor); view3dscene evaluates in single precision.
//   Each grid cell becomes two triangles (X_ITE splits along (u_i, v_j)-(u_i+1, v_j+1); view3dscene
//   writes an IndexedQuadSet that the renderer splits).
// Trimming (X_ITE only; view3dscene ignores trimming contours): every NurbsCurve2D is sampled the same
// way, n from its `tessellation` and its control point count, n + 1 points uniform over its own knot
// domain; a ContourPolyline2D is taken as it is. The loops are cut out of the grid's triangles in the
// unit square (libtess, odd winding) and the new vertices (loop points, loop-grid crossings) are
// placed by barycentric interpolation in the grid triangle they fall in: the trimmed border lies on
// the grid's triangles, not on the surface. Triangles under 1e-6 of the unit square are dropped.
//
// So a face is drawn within D when (1) the grid's triangles are within D of the surface and (2) every
// trimming chord, mapped through the surface, is within D of the curve's image. (1): on a grid cell of
// h_u x h_v the linear interpolant deviates by about (1/8)(h_u^2 M_uu + 2 h_u h_v M_uv + h_v^2 M_vv)
// (Filip, Magedson & Markot, as in surface_deviation_bound.hpp), M the largest normal curvatures; cells
// straddle knot lines (the grid ignores knots), so across a line where S is only C0 the term h/4 J is
// added, J a bound on the jump of the first derivative there (0 when the parametrisation is C1 after
// all, as at the joints of a rational circle's arcs). (2): a chord of a 2D curve sampled with step h
// deviates in (u,v) by at most h^2/8 |c''| + h/4 J (same reasoning), and a (u,v) error e moves the
// surface point by at most sqrt(2) L |e|, L the largest |S_u| and |S_v|. Each of (1) and (2) is held
// within kPlanningMargin D; they act in different directions (normal to the surface, along it).
// Where the figures come from: M and L are the tessellator's own planning samples
// (sample_patch_curvature.hpp, a 4 x 4 lattice of every Bezier patch) — estimates, at the price of 16
// evaluations a patch, since a viewer certifies nothing anyway; the cost grows with the square of the
// degree. The kink jumps and the trimming curves' |c''| are bounds from the control net: a rational
// derivative written as one polynomial over a power of W, in Bernstein form, bounded by its largest
// coefficient (terms that cancel in the true derivative cancel in the coefficients too), on the curve
// with every knot span split in 8 by knot insertion, so the small pieces' nets hug the shape. Both are
// one-dimensional, so these products cost the square of the degree, not its fourth power.
// Measured (tests/analysis/plan_tessellation_hints_test.cpp, on the viewer's grid sampled densely): a
// quarter cylinder within 1.13x of the fewest equal-angle chords, a trimming circle within 1.32x of the
// fewest uniform chords, a torus patch and a sphere within D.
//
// Counts: the surface pair (u, v) with the fewest grid cells that meets D, each direction at most 128
// segments (larger grids make X_ITE's trimming, which locates every trim point among all grid
// triangles, slow; a face that needs more gets 128); a trimming curve at most 256 segments. A direction
// whose default (2 x dimension) already meets D together with the other gets 0.
#include <vector>

#include "core/tessellation_hints.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

inline constexpr int kMaxSurfaceTessellation = 128;
inline constexpr int kMaxTrimTessellation = 256;

// Hints for a validated face and deviation > 0 (model units). Refuses (std::invalid_argument) a
// deviation that is not positive and finite.
TessellationHints plan_tessellation_hints(const TrimmedSurface& face, double deviation);

// Largest (u,v) distance between a 2D curve and its n uniform chords, per the bound above.
double uniform_chord_deviation_bound(const NurbsCurve& curve, int n);

}  // namespace cadnurbs
