#pragma once
// Reads the classic encoding (VRML97 "#VRML V2.0 utf8", X3D "#X3D V3.x utf8") into a node document, for
// the subset of node_schema.hpp: the nodes and fields cadnurbs writes, plus the few that simple NURBS
// files from other tools use. DEF/USE are resolved (a USE shares the DEF'd node). PROTO and EXTERNPROTO
// declarations are skipped (their nodes are read when the subset knows them); PROFILE, COMPONENT and
// META statements are skipped. This is not a general VRML parser: ROUTE, IMPORT/EXPORT, UNIT, Script and
// any other node are refused.
#include <string>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// Throws FileError "<name_for_errors>: line N: <reason>" (unsupported node or field, malformed value,
// unknown USE, unterminated node...).
NodeDocument parse_classic(const std::string& text, const std::string& name_for_errors);

}  // namespace cadnurbs
