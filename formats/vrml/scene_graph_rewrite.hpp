#pragma once
// A VRML97 / X3D file's whole scene graph written again in another encoding (or the same): every node,
// PROTO, Script, ROUTE, IMPORT and EXPORT kept, the NURBS nodes translated between VRML97's amendment
// and X3D's NURBS component (dialect_translation.hpp). No geometry is changed: the numbers pass as read.
#include <string>
#include <vector>

#include "formats/vrml/vrml_write_options.hpp"

namespace cadnurbs {

struct RewrittenSceneGraph {
  std::string text;                // the new file's text (not gzip'd)
  size_t nodes = 0;                // nodes written (each once, however often USE'd), PROTO bodies included
  size_t kinds = 0;                // their distinct types
  size_t routes = 0, protos = 0;   // ROUTE statements and PROTO / EXTERNPROTO declarations, bodies included
  std::vector<std::string> notes;  // what the translation dropped or declared, one line per kind
};

// `bytes`: the input file (gzip'd or not, classic or XML). `options`: encoding, self_contained,
// protos_url, pretty. Throws FileError "<name_for_errors>: line N: <reason>" as the reader does.
RewrittenSceneGraph rewrite_scene_graph(const std::string& bytes, const std::string& name_for_errors,
                                        const VrmlWriteOptions& options);

}  // namespace cadnurbs
