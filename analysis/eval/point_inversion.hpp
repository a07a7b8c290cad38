#pragma once
// Point inversion: the nearest point of a surface, or of a trimming curve's 3D image, to a given 3D
// point, by Newton iteration from a start value (Piegl & Tiller 6.1), kept inside the domain.
// Local: it finds the nearest point near the start, so callers supply good starts.
#include <Eigen/Core>

#include "analysis/eval/surface_evaluator.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

struct SurfaceProjection {
  Eigen::Vector2d uv;
  Eigen::Vector3d point;
  double distance;
};

// Newton on |S(u,v) - p|^2 from `start` (full Hessian when it is positive definite, Gauss-Newton
// otherwise), steps halved until the distance drops, (u,v) clamped to the domain.
SurfaceProjection project_to_surface(const SurfaceEvaluator& surface, const Eigen::Vector3d& p,
                                     const Eigen::Vector2d& start, int max_iterations = 30);

struct CurveProjection {
  double t;
  Eigen::Vector2d uv;
  Eigen::Vector3d point;
  double distance;
};

// Nearest point to p on S(c(t)), t in [t_lo, t_hi], by Gauss-Newton from t_start with step halving.
CurveProjection project_to_trim_curve(const SurfaceEvaluator& surface, const TrimSegment& segment,
                                      const Eigen::Vector3d& p, double t_start, double t_lo, double t_hi,
                                      int max_iterations = 30);

}  // namespace cadnurbs
