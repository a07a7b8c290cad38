#pragma once
// The knots' side of the fitters' hard constraints (seed 003 §5.2), shared by fit_curve and
// fit_surface: where interior knots start (averaged, then pushed apart), and how a conjugate-gradient
// step keeps them non-decreasing at least a minimum gap apart with the domain's ends [0, 1] fixed.
#include <Eigen/Core>
#include <vector>

namespace cadnurbs {

// Piegl & Tiller (9.69): the clamped knot vector on [0, 1] for `count` control points of `order` whose
// interior knot j is the mean of the parameters around position j·d, d = parameters / (count - degree),
// so that every span gets about the same number of samples. Takes non-decreasing parameters in [0, 1],
// at least count - degree + 1 of them (the callers check).
std::vector<double> averaged_knots(const std::vector<double>& parameters, int order, int count);

// Pushes the interior knots of a clamped vector on [0, 1] apart to at least `gap` (forward, then
// backward from the end at 1). Feasible whenever (count - order + 1) · gap < 1.
void keep_knot_gaps(std::vector<double>& knots, int order, int count, double gap);

// A block of `size` interior knots among a minimiser's unknowns: x[offset .. offset + size) holds them
// in units of the mean span (knot · scale, scale = the number of spans), so that the domain is
// [0, scale], its ends fixed, and a unit step moves a knot by about one span; `gap` is in those units.
struct KnotGapBlock {
  int offset = 0;
  int size = 0;
  double scale = 1;
  double gap = 0;

  // The largest a >= 0 keeping every gap of x + a·d (the domain's ends included) at least `gap`:
  // min over closing gaps of (u_{i+1} - u_i - gap) / (d_i - d_{i+1}); infinity when none closes.
  double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const;

  // The nearest direction that keeps the active gaps: along each chain of knots at the minimum gap the
  // components must not decrease (else the gap closes), an isotonic regression solved by pooling
  // adjacent violators into their average (seed 003: colliding knots move by their average); a chain
  // touching an end of the domain is held (the ends are fixed).
  void adjust(const Eigen::VectorXd& x, Eigen::VectorXd& d) const;
};

}  // namespace cadnurbs
