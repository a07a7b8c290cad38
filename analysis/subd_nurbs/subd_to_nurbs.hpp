#pragma once
// A Catmull-Clark SubD (SubdControlNet: Rhino's level 0) as NURBS patches, for the converters (issue 38).
//
// In: the net (points in model units), the deviation D (> 0, same units) the fitted patches must keep, and the first
// scene-wide edge number to use. Out: one TrimmedSurface per patch of the limit surface, over [0, 1]^2. A net of quads:
// one patch per quad, in face order, u from the quad's first point toward its second and v toward its last. A net with
// faces of 3, 5, ... sides: one patch per quad of the net after one Catmull-Clark step (so every patch side meets one
// patch side), face f's children in order, child k at the face's point k; a quad's child keeps the quad's orientation
// (child k covers the quad's quarter at its point k), another face's child k starts at point k with u toward point k +
// 1 and v toward point k - 1. Either way Su x Sv points where the face does (outward). Each is trimmed by its domain
// loop (domain_loop: sides v = 0, u = 1, v = 1, u = 0, counter-clockwise) whose TrimEdgeRefs number the sides; a side
// two patches share has one number, not reversed on one and reversed on the other, so the certified tessellator meshes
// the patches watertight; a closed SubD uses every number twice.
//
// Exact patches: a quad whose four points are regular (valence 4 inside; the boundary and crease cases OpenSubdiv
// treats as regular: a straight run of crease or boundary edges, corners of valence 2) is one uniform bicubic B-spline
// patch of its 4 x 4 points (phantom rows 2 P1 - P2 beyond boundaries and creases), written as its Bezier patch (orders
// 4, knots 0 0 0 0 1 1 1 1): exact to rounding. Fitted patches (every patch that holds an extraordinary point, a dart,
// a crease end...): clamped bicubic B-splines on knots graded toward both ends, 2^-k, ..., 1/4, 1/2, 3/4, ..., 1 - 2^-k
// (2k spans each way); on these knots the limit surface is exactly bicubic everywhere but the corner spans at the
// extraordinary points. Least squares to limit points sampled on a grid (5 per span and 6 more, geometric, inside each
// end span), the four boundary rows held: a side shared with an exact patch is that patch's Bezier side with the knots
// inserted (the same curve to rounding); a side between fitted patches is its own least-squares curve at the larger k
// of the two, ending at the limit positions, in both patches bit for bit where their k are equal, else by knot
// insertion (the same curve to rounding). Each fitted patch's k starts at 1 and goes up while the patch is not within D
// of the limit surface (patch_deviation.hpp: a bound proven on every regular piece of the limit, Bezier coefficients
// of the difference; sampled only in the squares of side 2^-10 at extraordinary features), at most 10 (OpenSubdiv's
// deepest isolation); a patch's knots are those of the largest k among itself and its fitted neighbours. Where patches
// meet at a point its control point is one value, bit for bit: the limit position there.
//
// Rules: Rhino's own (rhino_limit_surface.hpp): textbook Catmull-Clark but for the sector coefficients
// openNURBS puts on smooth edges at crease, corner and dart points. A patch those shape is fitted (graded knots
// with every span but the end ones halved, for the whole SubD) against the limit of the net refined 4 more
// steps under Rhino's rules: proven where that is Rhino's limit, sampled in its squares of side 1/16 at the
// tagged points. On the Rhino logo (corpus v7_rhino_logo_subd.3dm) every limit point Rhino caches is a patch
// corner to 1e-9 relative, but at the points of faces of 3 and 5 sides, which that file's Rhino build
// computed with an older rule (up to 0.014 mm off).
//
// Refuses (GeometryError(entity, reason)): what RhinoLimitSurface refuses (non-manifold edges, faces not consistently
// oriented, invalid nets), D <= 0, and a patch that stays above D at k = 10.
#include <string>
#include <vector>

#include "core/subd_control_net.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

struct SubdNurbs {
  std::vector<TrimmedSurface> patches;
  int edges_used = 0;  // edge numbers first_edge_number .. first_edge_number + edges_used - 1
  int exact_patches = 0, fitted_patches = 0;
  int rhino_rule_patches = 0;  // of the fitted ones, those Rhino's sector coefficients shape (see below)
  int fitted_levels = 0;       // the largest k of the fitted patches' knots: 2k spans, the end ones 2^-k (0: none)
  // Distance of the fitted patches from the limit surface at equal (u, v), hence also a bound on the distance between
  // the two surfaces either way: proven everywhere but the squares of side 2^-10 at extraordinary features, sampled (5
  // x 5 points each) in those. Exact patches: 0 to rounding.
  double fitted_bound = 0;
  double fitted_sampled_at_features = 0;
};

SubdNurbs subd_to_nurbs(const SubdControlNet& net, double deviation, int first_edge_number,
                        const std::string& entity = "SubD");

}  // namespace cadnurbs
