#include "formats/vrml/vrml_writer.hpp"

#include <stdexcept>

#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"
#include "formats/vrml/classic_encoding.hpp"
#include "formats/vrml/scene_to_nodes.hpp"
#include "formats/vrml/xml_encoding.hpp"

namespace cadnurbs {

std::string format_vrml(const Scene& scene, const VrmlWriteOptions& options) {
  if (options.coordinate_tolerance < 0.0) throw std::invalid_argument("coordinate tolerance must not be negative");
  if (options.significant_digits < 0 || options.significant_digits > 17)
    throw std::invalid_argument("significant digits must be between 1 and 17 (0: automatic)");
  validate(scene);
  const NodeDocument document = scene_to_nodes(scene, options);
  if (options.encoding == VrmlEncoding::x3d_xml) return xml_encoding(document, options.pretty);
  return classic_encoding(document, ClassicEncodingOptions{options.self_contained, options.protos_url, options.pretty});
}

void write_vrml(const std::string& path, const Scene& scene, const VrmlWriteOptions& options) {
  std::string text;
  try {
    text = format_vrml(scene, options);
  } catch (const FileError&) {
    throw;
  } catch (const std::exception& e) {
    throw FileError(path + ": " + e.what());
  }
  write_file_atomically(path, options.gzipped ? gzip(text) : text);
}

}  // namespace cadnurbs
