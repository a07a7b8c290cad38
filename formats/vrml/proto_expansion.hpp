#pragma once
// PROTO instances replaced by the nodes their PROTO's body stands for, so that geometry declared inside
// PROTOs reaches the Scene (nodes_to_scene.hpp).
//   In:  a node document's roots and its PROTO declarations (nested bodies' own PROTOs are in scope
//        inside their bodies, the innermost declaration of a name winning).
//   Out: copies of the roots in which every instance of a PROTO (or of an EXTERNPROTO whose url the
//        caller can load) is a copy of its body's first node (VRML97 4.8.3 / X3D 4.4.4.2: the first node
//        decides what the instance is; the others are not drawn), each "IS" field bound to the instance's
//        value of the PROTO field, else the declaration's default. Nodes shared by DEF/USE stay shared
//        within one expansion; each instance gets its own copy of its body.
//   Left as instances (still proto_instance, fields resolved): instances of an EXTERNPROTO whose urls
//        `load_extern` cannot load, and expansions nested deeper than kMaxProtoDepth (a PROTO that
//        instantiates itself, which VRML forbids, stops there instead of recursing without end).
// Throws std::length_error when the copies pass max_nodes nodes (a file multiplying PROTOs without bound).
#include <functional>
#include <string>
#include <vector>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

constexpr int kMaxProtoDepth = 32;

// The PROTO an EXTERNPROTO's url names and the file that declares it (its scope), both kept alive by the
// caller; proto null: not loadable.
struct LoadedProto {
  const NodeDocument* file = nullptr;
  const ProtoDeclaration* proto = nullptr;
};
using ExternProtoLoader = std::function<LoadedProto(const ProtoDeclaration& externproto)>;

struct ExpandedProtos {
  std::vector<NodePtr> roots;   // the document's roots, instances replaced
  size_t expanded = 0;          // instances replaced
  size_t body_routes = 0;       // ROUTEs inside the bodies expanded (not converted: animation)
  size_t body_extra_roots = 0;  // nodes after a body's first (not drawn)
};

ExpandedProtos expand_protos(const NodeDocument& document, const ExternProtoLoader& load_extern,
                             size_t max_nodes = 1000000);

}  // namespace cadnurbs
