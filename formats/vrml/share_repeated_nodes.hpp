#pragma once
// Writes each repeated piece of a node graph once (DEF/USE). A node whose text, as it will be written
// (numbers at their field's precision), equals an earlier node's is replaced by that node, which gets a
// generated DEF ("_<n>", vrml_identifier.hpp) and is USE'd after. Transforms whose children lists are
// equal keep their own transforms and share one Group holding the children: the instances of a part,
// the pins of a connector, the balls of a BGA. "Earlier" is file order (depth first, fields in order),
// the order in which the encodings write, so every USE follows its DEF.
// Left alone: named nodes (their DEF is a name from the scene), the document's roots, and nodes too small
// for a USE to save bytes. (A shared VRML97 NurbsGroup keeps meaning what an unnamed one means: the
// reader gathers its children into the parent, as for any generated DEF.)
#include "formats/vrml/vrml_identifier.hpp"
#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

void share_repeated_nodes(NodeDocument& document, IdentifierRegistry& ids);

}  // namespace cadnurbs
