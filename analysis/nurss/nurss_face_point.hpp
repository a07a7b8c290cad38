#pragma once
// The knot-interval factors of a NURSS face and its face point.
//
// For a face with corners P_0 .. P_{n-1} (indices mod n) and intervals d(a→b) (nurss_mesh.hpp), the
// paper's corner factor is
//     c_k = d(P_{k-1} → P_k) · d(P_{k+1} → P_k),
// the product of the intervals the two neighbours along the face hold toward P_k, and the face point is
//     V = Σ c_k P_k / Σ c_k     (on homogeneous points (w·P, w)).
// On a quad of a quadratic B-spline net (intervals D0, D1 across u, E0, E1 across v) V is the tensor
// product of the two edge points (D1·P_i + D0·P_{i+1}) / (D0 + D1), i.e. the surface point at the knot
// pair the face stands for: exactly on the limit surface wherever the net around is a tensor-product
// grid; elsewhere (faces at or near extraordinary faces) an approximation that converges with refinement.
//
// Vanishing intervals (ours; the paper does not say): if every c_k is 0 (all such faces are degenerate:
// e.g. between the two copies a double knot leaves after a step), c_k is the limit of the rule for
// intervals d + δ, δ → 0: c_k = d(P_{k-1} → P_k) + d(P_{k+1} → P_k); if that too is 0 everywhere, c_k = 1.
#include <vector>

#include "core/nurss_mesh.hpp"

namespace cadnurbs {

// c_0 .. c_{n-1} of face f, never all zero. Intervals must be set (validate).
std::vector<double> nurss_corner_factors(const NurssMesh& mesh, NurssFaceId f);

// V of face f as a homogeneous point (w·x, w·y, w·z, w).
Eigen::Vector4d nurss_face_point(const NurssMesh& mesh, NurssFaceId f);
// The same from f's factors when the caller has them already (nurss_corner_factors(mesh, f)).
Eigen::Vector4d nurss_face_point(const NurssMesh& mesh, NurssFaceId f, const std::vector<double>& factors);

// (x/w, y/w, z/w) of a homogeneous point.
inline Eigen::Vector3d euclidean(const Eigen::Vector4d& h) { return h.head<3>() / h.w(); }

}  // namespace cadnurbs
