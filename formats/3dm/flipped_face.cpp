#include "formats/3dm/flipped_face.hpp"

#include <utility>
#include <variant>

#include "formats/3dm/surface_objects.hpp"

namespace cadnurbs::rhino {

namespace {

// Swapping the coordinates mirrors the loop, which turns its direction; reversed() turns it back.
TrimLoop transposed(const TrimLoop& loop) {
  TrimLoop out = loop;
  for (auto& segment : out.segments) {
    if (auto* c = std::get_if<NurbsCurve>(&segment)) {
      for (auto& p : c->points) std::swap(p.x(), p.y());
    } else {
      for (auto& p : std::get<Polyline2D>(segment).points) std::swap(p.x(), p.y());
    }
  }
  return reversed(out);
}

}  // namespace

TrimmedSurface flipped(const TrimmedSurface& face) {
  TrimmedSurface out;
  out.surface = transposed(face.surface);
  out.loops.reserve(face.loops.size());
  for (const auto& loop : face.loops) out.loops.push_back(transposed(loop));
  return out;
}

}  // namespace cadnurbs::rhino
