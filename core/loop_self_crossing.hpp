#pragma once
// Where a trimming loop crosses itself, and the loop with the lobe on one side of that crossing cut off.
//
// Files carry edges with small loops of their own (KiCad's Bourns toroid windings: a B-spline edge on a
// planar face curls round by 0.1 mm, so the face's boundary crosses itself). Such a crossing splits the
// loop into two closed lobes; cutting one off leaves a loop that no longer crosses there, and changes the
// face by exactly the lobe's area.
//
// In:  a loop of 2D segments (NURBS pieces are sampled `samples_per_span` times per knot span; polylines
//      as they are), and `tolerance`, a distance in (u,v): two chords cross only where each one's ends lie
//      farther than it from the other's line (touching within round-off is not crossing).
// Out: find_self_crossing: the first crossing of two non-adjacent chords (none: the sampled loop is
//      simple; a crossing finer than the sampling can be missed). The crossing point is refined on the
//      curves themselves (Newton on c_a(t_a) = c_b(t_b)), so the cut pieces meet there to round-off.
//      cut_lobe: the loop without one lobe. The segments the cut passes through are split at the
//      crossing (split_curve; polylines at the interpolated point) and lose their edge references (the
//      edge they shared no longer matches the neighbouring face's); the others keep theirs.
#include <optional>
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

struct LoopSelfCrossing {
  // The loop runs segment `first` to parameter `first_t`, reaches the crossing point, runs on (the
  // "between" lobe) and comes back to it on segment `second` at `second_t`; the rest is the "outer" lobe.
  // first < second, or first == second with first_t < second_t.
  int first = 0;
  double first_t = 0;
  int second = 0;
  double second_t = 0;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double between_area = 0;  // signed area of the sampled lobe between, positive counter-clockwise
  double outer_area = 0;    // signed area of the rest of the loop
};

// Whether two non-adjacent chords of the closed polygon (last point != first) cross, as above: the quick
// test on a loop already sampled.
bool polygon_crosses_itself(const std::vector<Eigen::Vector2d>& polygon, double tolerance);

std::optional<LoopSelfCrossing> find_self_crossing(const TrimLoop& loop, int samples_per_span, double tolerance);

// Which lobe cut_lobe keeps.
enum class KeptLobe { between, outer };

TrimLoop cut_lobe(const TrimLoop& loop, const LoopSelfCrossing& crossing, KeptLobe kept);

}  // namespace cadnurbs
