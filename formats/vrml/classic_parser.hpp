#pragma once
// Reads the classic encoding (VRML97 "#VRML V2.0 utf8", X3D "#X3D V3.x/V4.x utf8") into a node document,
// for every node of node_schema.hpp. DEF/USE are resolved (a USE shares the DEF'd node). PROTO and
// EXTERNPROTO declarations give their interfaces (a PROTO's body is skipped) to the instances after them;
// an instance of a name the standard also has (white_dune declares the VRML97 amendment's NurbsSurface
// by EXTERNPROTO) is read as the standard's node, taking the fields only the PROTO declares too.
// Script (and shader) nodes' own field declarations are read with their values. ROUTE, IMPORT and
// EXPORT are recorded; PROFILE, COMPONENT and META are skipped; UNIT is refused (it would change what
// the numbers mean), and so is any unknown node or field, with the line.
#include <string>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// Throws FileError "<name_for_errors>: line N: <reason>" (unsupported node or field, malformed value,
// unknown USE, unterminated node...).
NodeDocument parse_classic(const std::string& text, const std::string& name_for_errors);

}  // namespace cadnurbs
