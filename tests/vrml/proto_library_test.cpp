// The PROTO library contract: split into PROTOs, EXTERNPROTO declarations, refusal of broken text.
#include <gtest/gtest.h>

#include "formats/vrml/nurbs_protos.hpp"
#include "formats/vrml/proto_library.hpp"

namespace cadnurbs {
namespace {

const char* const library_text =
    "#VRML V2.0 utf8\n"
    "# a header comment\n"
    "PROTO Alpha [\n"
    "  field SFInt32 count 3\n"
    "  # a comment inside the interface\n"
    "  field MFVec3f points [ 0 0 0, 1 1 1 ]\n"
    "  eventOut SFBool done\n"
    "] {\n"
    "  Group { children [\n"
    "  ] }\n"
    "}\n"
    "\n"
    "PROTO Beta [\n"
    "  exposedField MFNode children []\n"
    "] {\n"
    "  Alpha {}\n"
    "}\n";

TEST(ProtoLibrary, SplitsByTheContract) {
  const auto protos = parse_proto_library(library_text);
  ASSERT_EQ(protos.size(), 2u);
  EXPECT_EQ(protos[0].name, "Alpha");
  EXPECT_EQ(protos[0].line, 3);
  ASSERT_EQ(protos[0].interface.size(), 3u);
  EXPECT_EQ(protos[0].interface[1].kind, "field");
  EXPECT_EQ(protos[0].interface[1].type, "MFVec3f");
  EXPECT_EQ(protos[0].interface[1].name, "points");
  EXPECT_EQ(protos[0].interface[2].kind, "eventOut");
  EXPECT_TRUE(declares(protos[0], "done"));
  EXPECT_FALSE(declares(protos[0], "missing"));
  // The text runs from "PROTO" to the "}" at column 0, the indented "] }" inside staying in it.
  EXPECT_EQ(protos[0].text.rfind("PROTO Alpha [\n", 0), 0u);
  EXPECT_NE(protos[0].text.find("  ] }\n}\n"), std::string::npos);
  EXPECT_EQ(protos[1].text, "PROTO Beta [\n  exposedField MFNode children []\n] {\n  Alpha {}\n}\n");
}

TEST(ProtoLibrary, ExternProtoDropsDefaultsAndListsUrnsThenUrl) {
  const auto protos = parse_proto_library(library_text);
  EXPECT_EQ(externproto_declaration(protos[0], "lib.wrl"),
            "EXTERNPROTO Alpha [\n"
            " field SFInt32 count\n"
            " field MFVec3f points\n"
            " eventOut SFBool done\n"
            "] [\"urn:inet:blaxxun.com:node:Alpha\" \"lib.wrl#Alpha\"]\n");
}

TEST(ProtoLibrary, ExternProtoUrnsKeepView3dsceneOffItsX3DNodes) {
  // view3dscene maps "urn:web3d:vrml97:node:<Name>" to its built-in node of that name: wanted where
  // that node has our fields (NurbsSurface, NurbsGroup), a parse error for NurbsCurve2D and
  // Polyline2D (its X3D nodes, other fields), nothing drawn for TrimmedSurface and Contour2D.
  for (const auto& proto : nurbs_protos()) {
    const std::string d = externproto_declaration(proto, "cadnurbs-nurbs-protos.wrl");
    const bool castle = d.find("\"urn:web3d:vrml97:node:" + proto.name + "\"") != std::string::npos;
    EXPECT_EQ(castle, proto.name == "NurbsSurface" || proto.name == "NurbsGroup") << d;
    EXPECT_NE(d.find("\"urn:inet:blaxxun.com:node:" + proto.name + "\" \"cadnurbs-nurbs-protos.wrl#" + proto.name + "\"]"),
              std::string::npos)
        << d;
  }
}

TEST(ProtoLibrary, RefusesTextBreakingTheContract) {
  EXPECT_THROW(parse_proto_library("PROTO A [\n  field SFInt32 a 1\n"), std::runtime_error);  // no "] {"
  EXPECT_THROW(parse_proto_library("PROTO A [\n] {\n  Group {}\n"), std::runtime_error);   // no closing "}"
  EXPECT_THROW(parse_proto_library("PROTO A [\n  bogus line\n] {\n}\n"), std::runtime_error);
  EXPECT_THROW(parse_proto_library("PROTO A [\n] {\n}\nPROTO A [\n] {\n}\n"), std::runtime_error);
  try {
    parse_proto_library("\nPROTO A [\n  field SFInt32\n] {\n}\n");
    FAIL() << "accepted a declaration without a name";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("line 3: ", 0), 0u) << e.what();
  }
}

TEST(ProtoLibrary, EmbeddedLibraryFollowsTheContract) {
  // The real library is embedded at build time; it must parse and define the surface nodes we write.
  ASSERT_FALSE(nurbs_protos_library().empty()) << "formats/vrml/protos/cadnurbs-nurbs-protos.wrl was missing";
  const auto& protos = nurbs_protos();
  for (const char* name : {"NurbsSurface", "TrimmedSurface", "Contour2D", "NurbsCurve2D", "Polyline2D"}) {
    bool found = false;
    for (const auto& p : protos) found = found || p.name == name;
    EXPECT_TRUE(found) << name;
  }
}

}  // namespace
}  // namespace cadnurbs
