// face_areas: each face's mesh area (tessellate_to_deviation at D) against its trimmed NURBS area
// (trimmed_surface_area, as `info` integrates it), for issue 9's "no face covered twice".
//
//   face_areas [--fraction F] [--list] PART...      D = F x the part's bounding-box diagonal (1e-3)
//
// Per part: faces, how many differ by more than 0.1 % (0.5 % under 1 mm^2) above and below, the worst
// differences, and how many of those lie beyond the allowance of analysis/face_area_check (the boundary
// band and the curvature term).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "analysis/tessellate_to_deviation.hpp"
#include "analysis/face_area_check.hpp"
#include "converters/file_formats.hpp"
#include "core/bounding_box.hpp"

using namespace cadnurbs;

namespace {

void check(const std::string& path, double fraction, bool list) {
  const Scene exact = read_scene(path);
  const double d = fraction * scene_bounding_box(exact).diagonal().norm();
  const Scene meshed = tessellate_to_deviation(exact, d);
  std::vector<std::pair<const Shape*, const Shape*>> faces;
  std::function<void(const SceneNode&, const SceneNode&)> walk = [&](const SceneNode& a, const SceneNode& b) {
    for (size_t i = 0; i < a.shapes.size(); ++i) faces.emplace_back(&a.shapes[i], &b.shapes[i]);
    for (size_t i = 0; i < a.children.size(); ++i) walk(a.children[i], b.children[i]);
  };
  walk(exact.root, meshed.root);
  int counted = 0, over = 0, under = 0, beyond_band = 0;
  double worst_over = 0, worst_under = 0;
  for (const auto& [source, mesh] : faces) {
    const auto* face = std::get_if<TrimmedSurface>(&source->geometry);
    const auto* triangles = std::get_if<TriangleMesh>(&mesh->geometry);
    if (!face || !triangles) continue;
    const FaceAreaCheck check = check_face_area(*face, *triangles, d);
    const double relative = check.mesh_area / check.area - 1, limit = check.area < 1 ? 0.005 : 0.001;
    ++counted;
    worst_over = std::max(worst_over, relative);
    worst_under = std::min(worst_under, relative);
    if (std::abs(relative) <= limit) continue;
    (relative > 0 ? over : under) += 1;
    if (check.beyond()) ++beyond_band;
    if (list)
      std::printf("  %s %s: %+.3f %% of %.4g, allowance %.3g (%s)\n", display_name(*source).c_str(),
                  source->source_type.c_str(), 100 * relative, check.area, check.allowance,
                  check.beyond() ? "beyond" : "within");
  }
  std::printf("%s: D %.4g, %d faces, %d over and %d under the limit (%d beyond the allowance), worst %+.3f %% %+.3f %%\n",
              path.c_str(), d, counted, over, under, beyond_band, 100 * worst_over, 100 * worst_under);
}

}  // namespace

int main(int argc, char** argv) {
  double fraction = 1e-3;
  bool list = false;
  std::vector<std::string> parts;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--fraction") && i + 1 < argc) fraction = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--list")) list = true;
    else parts.emplace_back(argv[i]);
  }
  if (parts.empty() || !(fraction > 0)) {
    std::fprintf(stderr, "usage: face_areas [--fraction F] [--list] PART...\n");
    return 2;
  }
  for (const auto& part : parts) {
    try {
      check(part, fraction, list);
    } catch (const std::exception& e) {
      std::printf("%s: failed: %s\n", part.c_str(), e.what());
    }
  }
  return 0;
}
