#include "formats/3dm/oriented_loop.hpp"

#include "core/loop_closure.hpp"

namespace cadnurbs::rhino {

TrimLoop oriented_loop(TrimLoop loop, LoopRole role, double tolerance, const std::vector<int>& trim_numbers,
                       const std::string& loop_name) {
  close_loop_gaps(loop, tolerance, trim_numbers, loop_name);
  const double area = loop_signed_area(loop);
  if ((role == LoopRole::outer && area < 0) || (role == LoopRole::inner && area > 0)) return reversed(loop);
  return loop;
}

}  // namespace cadnurbs::rhino
