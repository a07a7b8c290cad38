#include "analysis/subd_nurbs/check_manifold.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "core/geometry_error.hpp"

namespace cadnurbs::subd_nurbs {

void check_manifold(const SubdControlNet& net, const std::string& entity) {
  validate(net, entity);
  auto for_each_side = [&](auto&& visit) {
    for (size_t f = 0; f < net.faces.size(); ++f)
      for (size_t k = 0; k < net.faces[f].size(); ++k)
        visit(static_cast<int>(f), net.faces[f][k], net.faces[f][(k + 1) % net.faces[f].size()]);
  };
  std::map<std::pair<int, int>, int> uses;
  for_each_side([&](int, int a, int b) {
    if (++uses[{std::min(a, b), std::max(a, b)}] == 3)
      throw GeometryError(entity, "edge " + std::to_string(std::min(a, b)) + "-" + std::to_string(std::max(a, b)) +
                                      " has 3 or more faces (non-manifold)");
  });
  std::map<std::pair<int, int>, int> face_of_side;
  for_each_side([&](int f, int a, int b) {
    const auto [side, fresh] = face_of_side.emplace(std::pair{a, b}, f);
    if (!fresh)
      throw GeometryError(entity, "faces " + std::to_string(side->second) + " and " + std::to_string(f) +
                                      " both run edge " + std::to_string(a) + "-" + std::to_string(b) +
                                      " the same way (orientation not consistent)");
  });
}

}  // namespace cadnurbs::subd_nurbs
