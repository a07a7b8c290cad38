#pragma once
// How strongly one rectangle of a surface's domain bends, sampled: the one place where the certified
// tessellator's grid planning (grid_planning.hpp) and the viewer hints (plan_tessellation_hints.hpp)
// learn how many steps a span needs.
//
// In: the surface and a rectangle [u0, u1] x [v0, v1] (a Bezier patch, or a span of one). Out:
// the largest normal components of the second derivatives (the second fundamental form: tangential
// acceleration moves points within the surface and costs no deviation), the normal's turning rate along
// a straight direction, and the largest |S_u| and |S_v| — each the largest over a 4 x 4 lattice of the
// rectangle. These are estimates, not bounds: the lattice can miss a maximum between its points. The
// tessellator certifies every triangle afterwards (triangle_certification.hpp); hints aim below D by
// kPlanningMargin instead.
#include "analysis/eval/surface_evaluator.hpp"

namespace cadnurbs::tessellation {

// Share of D that plans aim the sampled Filip-Magedson-Markot estimate at, so that the maxima the
// lattice misses still fit within D (the certificate corrects the few cells where they do not).
inline constexpr double kPlanningMargin = 0.85;

struct PatchCurvature {
  // |n . S_uu|, |n . S_uv|, |n . S_vv|; the whole |S_uu|, ... where no lattice point has a normal (a
  // patch degenerate throughout).
  double uu = 0, uv = 0, vv = 0;
  // The normal's turn per unit of u where u is straight (S_uu . n = 0), |L_uv| / |S_v across S_u|, and
  // likewise per unit of v: a cylinder's rulings do not turn it, a twisted ruled face's do.
  double turn_u = 0, turn_v = 0;
  double su = 0, sv = 0;  // largest |S_u| and |S_v|
};

// The patch [u0, u1] x [v0, v1], its far edges sampled an ulp inside: at a knot value the evaluator takes
// the next patch's derivatives (hammer.iges: one 0.003 wide beyond a face's edge, whose derivatives made the
// face's patch want 4096 cells across). The ends are given, not a width: u0 + (u1 - u0) may round past u1.
PatchCurvature sample_patch_curvature(const SurfaceEvaluator& surface, double u0, double u1, double v0, double v1);

}  // namespace cadnurbs::tessellation
