#pragma once
// A VRML97 PROTO library file written to the cadnurbs contract, split into its PROTOs so that a writer
// can declare the nodes it uses by EXTERNPROTO, or paste their definitions.
//
// The contract: each PROTO starts with a line "PROTO <Name> [" at column 0, then one interface
// declaration per line ("  field <Type> <name> <default>", "  exposedField ...", "  eventIn <Type> <name>",
// "  eventOut <Type> <name>"; blank and '#' lines allowed), then a line "] {", and the body ends with a
// line "}" at column 0. Everything outside PROTOs (header, comments) is ignored.
#include <string>
#include <vector>

namespace cadnurbs {

struct ProtoInterfaceDeclaration {
  std::string kind;  // field, exposedField, eventIn, eventOut
  std::string type;  // SFInt32, MFVec3f...
  std::string name;
};

struct ProtoDefinition {
  std::string name;
  std::vector<ProtoInterfaceDeclaration> interface;
  std::string text;  // the whole definition, from "PROTO" to its closing "}" line, newline-terminated
  int line = 0;      // where it starts in the library
};

// The PROTOs of `library` in file order. Throws std::runtime_error "line N: <reason>" where the text
// breaks the contract (an unterminated interface or body, an interface line that is not a declaration,
// a name defined twice).
std::vector<ProtoDefinition> parse_proto_library(const std::string& library);

// "EXTERNPROTO <Name> [ <declarations without defaults> ] [ <URNs> "<protos_url>#<Name>" ]",
// newline-terminated. URNs: "urn:inet:blaxxun.com:node:<Name>", preceded by
// "urn:web3d:vrml97:node:<Name>" for NurbsSurface and NurbsGroup only (view3dscene maps that URN to
// its built-in node of the name, which for the trimming nodes has other fields: see proto_library.cpp).
std::string externproto_declaration(const ProtoDefinition& proto, const std::string& protos_url);

// Whether the PROTO declares an interface entry called `name`.
bool declares(const ProtoDefinition& proto, const std::string& name);

}  // namespace cadnurbs
