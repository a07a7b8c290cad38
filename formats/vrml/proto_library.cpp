#include "formats/vrml/proto_library.hpp"

#include "formats/vrml/nurbs_protos.hpp"

#include <set>
#include <sstream>
#include <stdexcept>

namespace cadnurbs {

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

[[noreturn]] void fail(int line, const std::string& reason) {
  throw std::runtime_error("line " + std::to_string(line) + ": " + reason);
}

bool is_interface_kind(const std::string& w) {
  return w == "field" || w == "exposedField" || w == "eventIn" || w == "eventOut";
}

}  // namespace

std::vector<ProtoDefinition> parse_proto_library(const std::string& library) {
  std::vector<std::string> lines;
  {
    std::istringstream in(library);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines.push_back(line);
    }
  }
  std::vector<ProtoDefinition> protos;
  std::set<std::string> names;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("PROTO", 0) != 0) continue;
    const auto head = words(lines[i]);
    if (head.size() != 3 || head[0] != "PROTO" || head[2] != "[") {
      if (head.size() >= 1 && head[0] == "PROTO") fail(static_cast<int>(i + 1), "expected \"PROTO <Name> [\"");
      continue;
    }
    ProtoDefinition proto;
    proto.name = head[1];
    proto.line = static_cast<int>(i + 1);
    if (!names.insert(proto.name).second) fail(proto.line, "PROTO " + proto.name + " is defined twice");
    size_t j = i + 1;
    for (;; ++j) {
      if (j >= lines.size()) fail(proto.line, "interface of PROTO " + proto.name + " has no \"] {\" line");
      const std::string t = trimmed(lines[j]);
      if (t.empty() || t[0] == '#') continue;
      if (t[0] == ']') {
        if (trimmed(t.substr(1)) != "{") fail(static_cast<int>(j + 1), "expected \"] {\"");
        break;
      }
      const auto w = words(t);
      if (w.size() < 3 || !is_interface_kind(w[0]))
        fail(static_cast<int>(j + 1), "expected an interface declaration \"field <Type> <name> <default>\"");
      proto.interface.push_back({w[0], w[1], w[2]});
    }
    // Only a "}" at column 0 closes the body; indented braces belong to nodes inside it.
    size_t k = j + 1;
    while (k < lines.size() && !(lines[k].rfind('}', 0) == 0 && trimmed(lines[k]) == "}")) ++k;
    if (k >= lines.size()) fail(proto.line, "body of PROTO " + proto.name + " has no closing \"}\" at column 0");
    for (size_t n = i; n <= k; ++n) proto.text += lines[n] + "\n";
    protos.push_back(std::move(proto));
    i = k;
  }
  return protos;
}

// URNs of native implementations, tried before our PROTO file (first match wins):
// - "urn:inet:blaxxun.com:node:<Name>": blaxxun Contact / BS Contact, whose native nodes these are.
// - "urn:web3d:vrml97:node:<Name>": a URN no standard defines; Castle Game Engine (view3dscene) maps it
//   to its built-in node of that name. Listed only where that node has our fields and draws:
//   NurbsSurface and NurbsGroup (its VRML97 nodes, in newer versions; view3dscene 4.2 has none of them
//   and says "Unknown node URN", harmless). Never for NurbsCurve2D and Polyline2D: the URN maps to its
//   X3D nodes of those names (controlPoint, lineSegments instead of point), a parse error that skips
//   the rest of the file; nor for TrimmedSurface and Contour2D, whose nodes draw nothing and take only
//   those X3D curve nodes as children. X_ITE fetches no URN and uses the PROTO file. Details:
//   tests/viewers/README.md.
std::string externproto_declaration(const ProtoDefinition& proto, const std::string& protos_url) {
  std::string out = "EXTERNPROTO " + proto.name + " [\n";
  for (const auto& d : proto.interface) out += " " + d.kind + " " + d.type + " " + d.name + "\n";
  out += "] [";
  if (proto.name == "NurbsSurface" || proto.name == "NurbsGroup") out += "\"urn:web3d:vrml97:node:" + proto.name + "\" ";
  out += "\"urn:inet:blaxxun.com:node:" + proto.name + "\" \"" + protos_url + "#" + proto.name + "\"]\n";
  return out;
}

bool declares(const ProtoDefinition& proto, const std::string& name) {
  for (const auto& d : proto.interface)
    if (d.name == name) return true;
  return false;
}

// The embedded library (nurbs_protos.hpp), parsed once.
const std::vector<ProtoDefinition>& nurbs_protos() {
  static const std::vector<ProtoDefinition> protos = [] {
    try {
      return parse_proto_library(nurbs_protos_library());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("cadnurbs-nurbs-protos.wrl: " + std::string(e.what()));
    }
  }();
  return protos;
}

}  // namespace cadnurbs
