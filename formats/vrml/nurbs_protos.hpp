#pragma once
// The cadnurbs NURBS PROTO library (formats/vrml/protos/cadnurbs-nurbs-protos.wrl), embedded at build
// time: VRML97 implementations of the NURBS nodes that VRML97 output declares by EXTERNPROTO.
#include <string>
#include <vector>

#include "formats/vrml/proto_library.hpp"

namespace cadnurbs {

// The library file's text, so the command line can write it next to its outputs. Empty when the file
// was missing at build time.
const std::string& nurbs_protos_library();

// The library split into PROTOs (parsed once). Throws std::runtime_error naming the line when the
// embedded file breaks the PROTO library contract.
const std::vector<ProtoDefinition>& nurbs_protos();

}  // namespace cadnurbs
