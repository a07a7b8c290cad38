#pragma once
// Reads the X3D XML encoding into a node document, for the subset of node_schema.hpp. A small hand
// parser for what X3D files use: the XML declaration, DOCTYPE, comments, elements with single- or
// double-quoted attributes, the five named entities and numeric character references. <head> is skipped;
// DEF/USE and containerField are honoured. CDATA (scripts), ROUTE, ProtoDeclare/ProtoInstance and any
// node outside the subset are refused.
#include <string>

#include "formats/vrml/x3d_node.hpp"

namespace cadnurbs {

// Throws FileError "<name_for_errors>: line N: <reason>".
NodeDocument parse_xml(const std::string& text, const std::string& name_for_errors);

}  // namespace cadnurbs
