#pragma once
// Reads the X3D XML encoding into a node document, for every node of node_schema.hpp, on top of the
// small XML reader of xml_markup.hpp. <head> is skipped (a <unit> in it is refused: it would change what
// the numbers mean); DEF/USE and containerField are honoured (a missing containerField that names no node
// field of the parent falls back to "children"). ROUTE, IMPORT and EXPORT are recorded; ProtoDeclare and
// ExternProtoDeclare give their interfaces (a body is not read) to the ProtoInstances after them; a
// Script's <field> declarations are read with their values (its source, CDATA, is not kept). An unknown
// node, or a field the node does not have, is refused with the line.
#include <string>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// Throws FileError "<name_for_errors>: line N: <reason>".
NodeDocument parse_xml(const std::string& text, const std::string& name_for_errors);

}  // namespace cadnurbs
