#pragma once
// One refinement step of quadratic NURSS (Sederberg, Zheng, Sewell & Sabin 1998, non-uniform
// Doo-Sabin; seed 001 fig. 2.14). Like Doo-Sabin, every face corner (face f, corner i) gets a new vertex
// P'_i; they are joined into an F-face per old face, an E-face (quad) per interior edge and a V-face
// per interior vertex (one corner per face around it). Boundary edges and boundary vertices make no face,
// so an open net stays open.
//
// Position of P'_i in a face P_0 .. P_{n-1} (indices mod n, on homogeneous points (w·P, w)), with c_k and
// V from nurss_face_point.hpp:
//     P'_i = (P_i + V) / 2
//            + (c_{i+2} + c_{i-2}) / (8 Σ_k c_k) · ( -n P_i + Σ_j (1 + 2 cos(2π (i - j) / n)) P_j ).
// With all intervals equal it is Doo-Sabin's rule: P'_i = Σ_j α_ij P_j, α_ii = 1/4 + 5/(4n),
// α_ij = (3 + 2 cos(2π(i-j)/n)) / (4n). On a quad of a quadratic B-spline net (corner intervals D0, D1
// across u, E0, E1 across v) it is the tensor product of the curve rules
//     Q = ((D0 + 2 D1) P_i + D0 P_{i+1}) / (2 (D0 + D1))   (and the same across v),
// i.e. knot insertion at the midpoint of every knot interval (the test checks this against refine_knots).
//
// New knot intervals, halved (the paper): P'_i is a vertex of four edges, two along the old side
// P_i P_{i+1} (its F-edge to P'_{i+1}, and its V-edge across the old side P_{i-1} P_i) and two along the old
// side P_i P_{i-1} (its F-edge to P'_{i-1}, and its V-edge across P_i P_{i+1}); it holds d(P_i → P_{i+1})/2
// on the first two and d(P_i → P_{i-1})/2 on the other two.
//
// Numbering (relied on by tests and callers): new vertex of (face f, corner i) = Σ_{g<f} |g| + i; new face
// f = the F-face of old face f (same corner order), then the E-faces in edge order, then the V-faces in
// vertex order. Labels: an F-face keeps its face's label, an E-face or V-face takes the largest label of
// the old faces around it.
#include "core/nurss_mesh.hpp"

namespace cadnurbs {

// The mesh after one step. Refuses (GeometryError, via validate) a mesh with unset intervals, bad
// weights or two-face vertex rings.
NurssMesh refine_nurss(const NurssMesh& mesh);

// `levels` steps (0: the mesh itself).
NurssMesh refine_nurss(const NurssMesh& mesh, int levels);

}  // namespace cadnurbs
