#include "formats/vrml/vrml_reader.hpp"

#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"
#include "formats/vrml/animation_at_rest.hpp"
#include "formats/vrml/classic_parser.hpp"
#include "formats/vrml/nodes_to_scene.hpp"
#include "formats/vrml/xml_parser.hpp"

namespace cadnurbs {

NodeDocument parse_vrml_document(const std::string& bytes, const std::string& name_for_errors) {
  // .wrz, .wrl.gz, .x3dvz, .x3dz, or any of the plain names holding gzip'd text, as browsers accept.
  const std::string unpacked = is_gzip(bytes) ? gunzip(bytes, name_for_errors) : std::string();
  const std::string& text = is_gzip(bytes) ? unpacked : bytes;
  size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  const size_t first = text.find_first_not_of(" \t\r\n", start);
  if (first != std::string::npos && text[first] == '<') return parse_xml(text, name_for_errors);
  return parse_classic(start ? text.substr(start) : text, name_for_errors);
}

SceneFromNodes parse_vrml_scene(const std::string& bytes, const std::string& name_for_errors,
                                bool homogeneous_control_points) {
  NodeDocument document = parse_vrml_document(bytes, name_for_errors);
  std::vector<std::string> rest_notes = apply_animation_at_rest(document);
  SceneFromNodes out = nodes_to_scene(document, name_for_errors, homogeneous_control_points);
  out.notes.insert(out.notes.begin(), rest_notes.begin(), rest_notes.end());
  return out;
}

Scene parse_vrml(const std::string& bytes, const std::string& name_for_errors, bool homogeneous_control_points) {
  return parse_vrml_scene(bytes, name_for_errors, homogeneous_control_points).scene;
}

Scene read_vrml(const std::string& path, bool homogeneous_control_points) {
  return parse_vrml(read_file(path), path, homogeneous_control_points);
}

SceneFromNodes read_vrml_scene(const std::string& path, bool homogeneous_control_points) {
  return parse_vrml_scene(read_file(path), path, homogeneous_control_points);
}

}  // namespace cadnurbs
