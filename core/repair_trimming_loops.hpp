#pragma once
// The one check of a face's trimming loops that every reader's output passes before any writer or
// tessellation sees it, so that `convert -o x.x3dv` and `convert --mesh` treat every face the same
// way. Repairs what can be repaired with certainty; refuses the rest (the STEP/IGES path then writes
// that face as OCCT's mesh of it, other inputs fail with the face named).
//
// Repairs (each reported as one line):
//  - a loop that bounds no area (|signed area| <= 1e-12 of the domain's): dropped; it trims nothing;
//  - a loop further out that lies whole periods away in a direction where the surface joins itself
//    (its first and last rows of control points coincide, weights too): moved back by those periods;
//  - with LoopsOutsideDomain::cut, any other loop further out: cut to the domain (clip_loop_to_domain);
//  - a loop whose samples leave the surface's domain by at most kDomainSlack of its size: the points
//    that define it (2D control points, polyline points) outside by up to twice that much are moved
//    onto the domain's edge. A B-spline lies in the convex hull of its control points, so the curve
//    moves by no more than they do, and the surface is evaluated clamped at its edge anyway. Points
//    further out (an arc's control polygon near the edge, the arc inside) are left alone. Excursions
//    of round-off size (1e-12 of the domain) are repaired without a report line;
//  - a loop that crosses itself (two of its non-adjacent chords properly cross, with each NURBS piece
//    sampled 16 and again 128 times per knot span; a crossing finer than that can be missed, and a
//    loop that only touches itself within 1e-9 of the domain does not cross) where the lobe on one side
//    of the crossing bounds at most a tenth of the other's area: that lobe is cut off (core/
//    loop_self_crossing), up to 8 lobes a loop. The face changes by the lobe's area, reported as a share.
// Refusals (GeometryError(entity, reason)):
//  - a loop further outside the domain (LoopsOutsideDomain::refuse), or no loop meeting it (cut);
//  - a loop that crosses itself with larger lobes (a bow tie);
//  - a face all of whose loops bound no area.
#include <string>
#include <vector>

#include "core/geometry_error.hpp"
#include "core/scene.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// Largest distance, relative to the domain's size in each direction, by which a loop may leave the
// domain and still be moved onto it (11752.stp's pcurves leave a B-spline's domain by 1.5e-3).
constexpr double kDomainSlack = 1e-2;

// What a loop further outside the domain than kDomainSlack (and not whole periods away) means.
enum class LoopsOutsideDomain {
  refuse,  // a fault: B-rep files, whose loops are the faces' edges (STEP/IGES then mesh the face by OCCT)
  cut,     // GLU's rule, which VRML/X3D viewers follow: only the part inside the domain is drawn
};

// The refusal of a face that has no area (every loop bounds none, or none meets the domain): nothing of
// it can be drawn or meshed, so a scene drops it (repair_trimming_loops(Scene&)) instead of failing.
class FaceWithoutArea : public GeometryError {
 public:
  using GeometryError::GeometryError;
};

// Repairs `face`'s loops in place; returns what was done, one line per repair (empty: nothing).
// Throws GeometryError(entity, reason) when the loops cannot be repaired with certainty.
std::vector<std::string> repair_trimming_loops(TrimmedSurface& face, const std::string& entity,
                                               LoopsOutsideDomain outside = LoopsOutsideDomain::refuse);

// Every trimmed surface of the scene; lines "PATH: what was done", PATH named as validate(Scene) names
// shapes. A face without area is taken out of the scene ("PATH: REASON: dropped"), and so is a face
// the repair refuses ("PATH: REASON: face left out"): one bad face never costs the file (a file left
// without geometry is then refused by the conversion, naming these lines).
std::vector<std::string> repair_trimming_loops(Scene& scene, LoopsOutsideDomain outside = LoopsOutsideDomain::refuse);

}  // namespace cadnurbs
