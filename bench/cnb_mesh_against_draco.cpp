// cnb_mesh_against_draco: .cnb's traversal-coded triangle mesh against Draco (the smallest file within D
// that report/smallest_compressed_mesh finds) on the same certified tessellations, part by part.
//
// For each part and each D: for each tessellation fraction f of encode_mesh_within (0.5, 0.7, 0.85), the
// certified world mesh at f·D is coded (1) by Draco at its coarsest bits within (1 - f)·D, and (2) as a
// .cnb holding that mesh alone, quantised on the grid q = 2·(1 - f)·D/√3 (so a vertex moves by at most
// (1 - f)·D). Each side keeps its smallest file over f. Our file is decoded and checked: its triangles are the
// tessellation's with every corner rounded to the grid (so moved by at most q·√3/2 <= (1 - f)·D), and the
// writer's bound is at most D. Prints one line per part and D and the totals, with Draco/.cnb as a ratio of totals.
//
//   cnb_mesh_against_draco D1[,D2...] PART.step...
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/mesh/oriented_triangle_keys.hpp"
#include "converters/file_formats.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "report/smallest_compressed_mesh.hpp"

using namespace cadnurbs;

namespace {

struct Sizes {
  long draco = 0, cnb = 0;
};

// Our smallest .cnb of the part's certified meshes within D, checked after decoding.
long smallest_cnb(const Scene& part, double d, const std::vector<double>& fractions) {
  long best = 0;
  for (double f : fractions) {
    TessellationReport report;
    TriangleMesh mesh = certified_world_mesh(part, f * d, &report);
    const double certified = std::max(report.certified_deviation, f * d);
    if (report.uncertified_triangles > 0 || certified >= d) continue;
    mesh.corner_normals.clear();
    Scene scene;
    scene.unit = part.unit;
    scene.root.name = part.root.name;
    scene.root.shapes.push_back({"mesh", mesh, std::nullopt});
    CnbOptions options;
    options.max_deviation = d;
    options.trim_share = f;
    options.mesh_deviation = std::min(certified, f * d);
    CnbWriteReport written;
    const std::string bytes = write_cnb(scene, options, &written);
    const Scene decoded = read_cnb(bytes, "bench");
    const auto& out = std::get<TriangleMesh>(decoded.root.shapes.at(0).geometry);
    const double step = written.point_step;
    std::vector<Eigen::Vector3d> rounded;
    for (const auto& p : mesh.positions)
      rounded.emplace_back(std::llround(p.x() / step) * step, std::llround(p.y() / step) * step,
                           std::llround(p.z() / step) * step);
    if (oriented_triangle_keys(out.positions, out.triangles) != oriented_triangle_keys(rounded, mesh.triangles))
      throw std::runtime_error("the decoded triangles are not the tessellation's rounded to the grid");
    if (written.deviation_bound() > d * (1 + 1e-12)) throw std::runtime_error("the bound exceeds D");
    if (best == 0 || static_cast<long>(bytes.size()) < best) best = static_cast<long>(bytes.size());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: cnb_mesh_against_draco D1[,D2...] PART.step...\n");
    return 2;
  }
  std::vector<double> deviations;
  std::stringstream list(argv[1]);
  for (std::string item; std::getline(list, item, ',');) deviations.push_back(std::stod(item));
  const MeshEncodingOptions options;
  std::map<double, Sizes> totals;
  std::printf("| part | D | Draco | .cnb mesh | Draco / .cnb |\n|---|---|---|---|---|\n");
  for (int i = 2; i < argc; ++i) {
    const Scene part = read_scene(argv[i]);
    const std::string name = std::string(argv[i]).substr(std::string(argv[i]).find_last_of('/') + 1);
    for (double d : deviations) {
      Sizes s;
      try {
        s.draco = encode_mesh_within(part, d, MeshCodec::draco, options).raw_bytes;
      } catch (const std::exception& e) {
        std::printf("| %s | %g | (Draco: %s) | | |\n", name.c_str(), d, e.what());
        continue;
      }
      s.cnb = smallest_cnb(part, d, options.fractions);
      totals[d].draco += s.draco;
      totals[d].cnb += s.cnb;
      std::printf("| %s | %g | %ld | %ld | %.2f |\n", name.c_str(), d, s.draco, s.cnb, double(s.draco) / double(s.cnb));
      std::fflush(stdout);
    }
  }
  for (const auto& [d, s] : totals)
    std::printf("| total | %g | %ld | %ld | %.2f |\n", d, s.draco, s.cnb, double(s.draco) / double(s.cnb));
}
