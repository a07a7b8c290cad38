#pragma once
// The classic (curly-brace) text encoding of a node document:
//   VRML97:      "#VRML V2.0 utf8", then an EXTERNPROTO declaration (or, self-contained, the PROTO
//                definition) from the cadnurbs NURBS PROTO library for every NURBS node the document uses.
//   X3D classic: "#X3D V3.3 utf8", "PROFILE Interchange", "COMPONENT NURBS:4".
// Layout, compact (the default): no indent; a node's fields on its line, each child node of an MFNode on a
// line of its own, array tuples one per line. Pretty: one field per line, one space of indent per level,
// small nodes on one line. Both read alike; compact saves the indent bytes.
#include <set>
#include <string>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

struct ClassicEncodingOptions {
  bool self_contained = false;                            // VRML97: paste PROTOs instead of EXTERNPROTO
  std::string protos_url = "cadnurbs-nurbs-protos.wrl";   // VRML97: EXTERNPROTO URL before "#<Name>"
  bool pretty = false;                                    // indented, one field per line
};

// The document as text. For VRML97, refuses (std::runtime_error) a NURBS node the PROTO library does not
// define, or a field the library's PROTO does not declare.
std::string classic_encoding(const NodeDocument& document, const ClassicEncodingOptions& options);

// Node types reachable from the document's roots (each node once, however often it is USE'd).
std::set<std::string> node_types_used(const NodeDocument& document);

}  // namespace cadnurbs
