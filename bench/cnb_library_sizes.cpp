// cnb_library_sizes: the .cnb that `convert --deviation D -o P.cnb` writes against the smallest Draco
// and meshoptimizer files within the same D (report/smallest_compressed_mesh), part by part (issue 39).
//
// For each STEP part and each D: the scene as convert reads it, its compact form (compact_scene at the
// written tolerance, as convert makes it), and cnb_coding's file of that (every body as NURBS or as a
// certified mesh, whichever codes smaller); Draco (raw bytes) and meshoptimizer (gzip'd, gltfpack's
// way) of the certified mesh within D at their smallest over the tessellation fractions. One line of
// tab-separated values per part and D:
//
//   family  part  D  cnb  draco  meshopt_gz  bodies  bodies_meshed  cnb_bound  note
//
// (family = the part's folder; 0 bytes and a note where a codec refused the part). Aggregate with
// bench/cnb_library_table.py. Split a library over processes with xargs -P.
//
//   cnb_library_sizes [--detail] 0.01,1,1e-3d PART.step...   (1e-3d: 1e-3 of the part's diagonal)
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/compaction/compact_scene.hpp"
#include "converters/cnb_coding.hpp"
#include "converters/file_formats.hpp"
#include "converters/scene_preparation.hpp"
#include "core/bounding_box.hpp"
#include "report/smallest_compressed_mesh.hpp"

using namespace cadnurbs;

int main(int argc, char** argv) {
  // --detail: each .cnb's payload by kind of field, on stderr.
  const bool detail = argc > 1 && std::string(argv[1]) == "--detail";
  if (detail) {
    --argc;
    ++argv;
  }
  if (argc < 3) {
    std::fprintf(stderr, "usage: cnb_library_sizes [--detail] D1[,D2...] PART.step...\n");
    return 2;
  }
  // D in scene units, or with a trailing 'd' a fraction of the part's bounding-box diagonal.
  std::vector<std::pair<double, bool>> deviations;
  std::stringstream list(argv[1]);
  for (std::string item; std::getline(list, item, ',');)
    deviations.emplace_back(std::stod(item), !item.empty() && item.back() == 'd');
  MeshEncodingOptions mesh_options;
  mesh_options.measure_after_decoding = false;  // the bound is replayed and checked after decoding
  for (int i = 2; i < argc; ++i) {
    const std::filesystem::path path(argv[i]);
    const std::string family = path.parent_path().filename().string(), part = path.filename().string();
    Scene scene, compact;
    try {
      scene = read_scene(path.string());
      compact = compact_scene(scene, written_tolerance(scene, 0));
    } catch (const std::exception& e) {
      std::printf("%s\t%s\t\t0\t0\t0\t0\t0\t0\tread: %s\n", family.c_str(), part.c_str(), e.what());
      continue;
    }
    const double diagonal = scene_bounding_box(scene).diagonal().norm();
    for (const auto& [value, relative] : deviations) {
      const double d = relative ? value * diagonal : value;
      long cnb = 0, draco = 0, meshopt = 0;
      int bodies = 0, meshed = 0;
      double bound = 0;
      std::string note;
      try {
        const CnbCoding coded = cnb_coding(compact, d, &scene);
        cnb = static_cast<long>(coded.bytes.size());
        bodies = coded.choice.bodies;
        meshed = coded.choice.bodies_meshed;
        bound = coded.written.deviation_bound();
        if (detail) {
          const CnbWriteReport& w = coded.written;
          std::fprintf(stderr, "%s at %g: payload %zu (points %zu, trims %zu, knots %zu, weights %zu, float64 %zu, other %zu), file %zu; %ld spare trim knots removed\n",
                       part.c_str(), d, w.payload_bytes, w.point_bytes, w.trim_bytes, w.knot_bytes, w.weight_bytes,
                       w.float_bytes, w.other_bytes, w.file_bytes, w.trim_knots_removed);
          const CodingChoiceReport& c = coded.choice;
          std::fprintf(stderr, "%s at %g: candidates as is %zu, per body %zu, all meshed %zu, exact meshed %zu, merged meshes %zu; %d of %d bodies meshed\n",
                       part.c_str(), d, c.as_is_bytes, c.per_body_bytes, c.all_meshed_bytes, c.exact_meshed_bytes,
                       c.merged_meshes_bytes, c.bodies_meshed, c.bodies);
        }
      } catch (const std::exception& e) {
        note += std::string("cnb: ") + e.what() + "; ";
      }
      try {
        const auto encoded = encode_mesh_within(scene, d, {MeshCodec::draco, MeshCodec::meshopt}, mesh_options);
        draco = encoded[0].raw_bytes;
        meshopt = encoded[1].gzip_bytes;
      } catch (const std::exception& e) {
        note += std::string("meshes: ") + e.what();
      }
      std::printf("%s\t%s\t%g\t%ld\t%ld\t%ld\t%d\t%d\t%.6g\t%s\n", family.c_str(), part.c_str(), d, cnb, draco, meshopt,
                  bodies, meshed, bound, note.c_str());
      std::fflush(stdout);
    }
  }
}
