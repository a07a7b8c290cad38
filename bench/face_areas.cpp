// face_areas: each face's mesh area (tessellate_to_deviation at D) against its trimmed NURBS area
// (trimmed_surface_area, as `info` integrates it), for issue 9's "no face covered twice".
//
//   face_areas [--fraction F] [--list] PART...      D = F x the part's bounding-box diagonal (1e-3)
//
// Per part: faces, how many differ by more than 0.1 % (0.5 % under 1 mm^2) above and below, the worst
// differences, and how many of those lie beyond the allowance of analysis/measure/face_area_check (the boundary
// band and the curvature term).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/measure/face_area_check.hpp"
#include "converters/file_formats.hpp"
#include "core/bounding_box.hpp"

using namespace cadnurbs;

namespace {

void check(const std::string& path, double fraction, bool list) {
  const Scene exact = read_scene(path);
  const double d = fraction * scene_bounding_box(exact).diagonal().norm();
  const Scene meshed = tessellate_to_deviation(exact, d);
  int counted = 0, over = 0, under = 0, beyond = 0;
  double worst_over = 0, worst_under = 0;
  for (const auto& [face, check] : check_face_areas(exact, meshed, d)) {
    const double relative = check.mesh_area / check.area - 1;
    ++counted;
    worst_over = std::max(worst_over, relative);
    worst_under = std::min(worst_under, relative);
    if (std::abs(relative) <= check.relative_limit) continue;
    (relative > 0 ? over : under) += 1;
    if (check.beyond()) ++beyond;
    if (list)
      std::printf("  %s %s: %+.3f %% of %.4g, allowance %.3g (%s)\n", display_name(*face).c_str(),
                  face->source_type.c_str(), 100 * relative, check.area, check.allowance,
                  check.beyond() ? "beyond" : "within");
  }
  std::printf("%s: D %.4g, %d faces, %d over and %d under the limit (%d beyond the allowance), worst %+.3f %% %+.3f %%\n",
              path.c_str(), d, counted, over, under, beyond, 100 * worst_over, 100 * worst_under);
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
