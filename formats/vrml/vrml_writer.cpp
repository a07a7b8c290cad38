#include "formats/vrml/vrml_writer.hpp"

#include <cctype>
#include <stdexcept>

#include "formats/common/file_io.hpp"
#include "formats/vrml/classic_encoding.hpp"
#include "formats/vrml/scene_to_nodes.hpp"
#include "formats/vrml/xml_encoding.hpp"

namespace cadnurbs {

std::optional<VrmlEncoding> encoding_for_extension(const std::string& ext) {
  std::string e;
  for (char c : ext) e.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  if (!e.empty() && e[0] == '.') e.erase(0, 1);
  if (e == "wrl") return VrmlEncoding::vrml97;
  if (e == "x3dv") return VrmlEncoding::x3d_classic;
  if (e == "x3d") return VrmlEncoding::x3d_xml;
  return std::nullopt;
}

std::string format_vrml(const Scene& scene, const VrmlWriteOptions& options) {
  if (options.coordinate_tolerance < 0.0) throw std::invalid_argument("coordinate tolerance must not be negative");
  if (options.significant_digits < 0 || options.significant_digits > 17)
    throw std::invalid_argument("significant digits must be between 1 and 17 (0: automatic)");
  validate(scene);
  const NodeDocument document = scene_to_nodes(scene, options);
  if (options.encoding == VrmlEncoding::x3d_xml) return xml_encoding(document);
  return classic_encoding(document, ClassicEncodingOptions{options.self_contained, options.protos_url});
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
  write_file_atomically(path, text);
}

}  // namespace cadnurbs
