#include "converters/conversion_record.hpp"

#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "converters/file_formats.hpp"
#include "converters/scene_preparation.hpp"
#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"
#include "report/storage_accounting.hpp"

namespace cadnurbs {

std::string record_error(std::string message, const std::string& input) {
  if (message.starts_with(input + ": ")) message.erase(0, input.size() + 2);
  return message;
}

PartRecord conversion_record(const std::string& input, const BrepTranslation& loaded) {
  PartRecord record;
  record.input = input;
  for (const auto& line : loaded.notes) record.warnings.push_back(line);
  for (const auto& line : loaded.repairs) record.warnings.push_back(line);
  for (const auto& f : loaded.fallbacks)
    record.warnings.push_back(f.node + " face " + std::to_string(f.face_index) + " (" + f.surface_type +
                              ") as a mesh: " + f.reason);
  const Scene& scene = loaded.scene;
  record.unit = scene.unit.name;
  record.diagonal = checked_diagonal(scene, input);
  record.deviation = record.diagonal > 0 ? default_deviation(record.diagonal, input) : 0.0;
  record.nurbs = nurbs_storage(scene);
  return record;
}

void add_written_file(PartRecord& record, const std::string& key, const std::string& path, const Scene& written,
                      const ConversionResult& result) {
  const FileFormat& format = output_format(path);
  const std::string extension = file_extension(path);
  RepresentationFigures f;
  f.key = key;
  f.label = format.name + ", as convert writes it";
  const bool mesh = result.mesh || result.steps > 0;
  f.kind = mesh ? RepresentationKind::mesh : RepresentationKind::nurbs;
  const std::string bytes = read_file(path);
  f.bytes = static_cast<long>(bytes.size());
  f.gzip_bytes = is_gzip(bytes) ? f.bytes : static_cast<long>(gzip(bytes).size());
  if (mesh) {
    const MeshStorage storage = mesh_storage(weld_exact(scene_triangles(written)));
    f.floats = extension == ".stl" ? storage.soup_floats_with_normals : storage.indexed_floats;
    f.integers = extension == ".stl" ? 0 : storage.indexed_integers;
    if (result.mesh && record.mesh.vertices == 0) {
      record.mesh = storage;
      record.mesh_certified_deviation = result.mesh->report.certified_deviation;
    }
  } else {
    const NurbsStorage storage = nurbs_storage(written);
    f.floats = storage.total_floats();
    f.integers = storage.polygon_corners;
  }
  f.deviation = result.deviation_bound;  // NaN where no bound is known: the record says not known
  f.deviation_basis = result.deviation_basis;
  f.deviation_kind = DeviationKind::bound;
  record.representations.push_back(f);
}

}  // namespace cadnurbs
