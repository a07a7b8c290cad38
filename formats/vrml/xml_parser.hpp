#pragma once
// Reads the X3D XML encoding into a node document, for the subset of node_schema.hpp, on top of the
// small XML reader of xml_markup.hpp. <head> is skipped; DEF/USE and containerField are honoured (a
// missing containerField that names no node field of the parent falls back to "children"). ROUTE,
// ProtoDeclare/ProtoInstance, Script and any other node outside the subset are refused.
#include <string>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// Throws FileError "<name_for_errors>: line N: <reason>".
NodeDocument parse_xml(const std::string& text, const std::string& name_for_errors);

}  // namespace cadnurbs
