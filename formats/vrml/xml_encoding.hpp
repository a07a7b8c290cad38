#pragma once
// The X3D XML encoding of an X3D node document: <X3D profile='Interchange' version='3.3'> with
// <head><component name='NURBS' level='4'/></head>, then the nodes as elements inside <Scene>. Child
// elements carry containerField only where it differs from the node's default; one element per line,
// indented by depth only when `pretty`; array tuples one per line.
#include <string>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// The document as X3D XML. Refuses (std::invalid_argument) a VRML97 document: the VRML97 NURBS nodes
// have no XML encoding.
std::string xml_encoding(const NodeDocument& document, bool pretty = false);

// `text` escaped for a single-quoted XML attribute (& < > ' and line breaks).
std::string xml_escaped(const std::string& text);

}  // namespace cadnurbs
