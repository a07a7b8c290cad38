#include "formats/vrml/nurbs_interpolator_text.hpp"

#include <stdexcept>

#include "formats/vrml/classic_tokenizer.hpp"
#include "formats/vrml/node_text.hpp"
#include "formats/vrml/nurbs_protos.hpp"
#include "formats/vrml/proto_library.hpp"
#include "formats/vrml/xml_encoding.hpp"
#include "formats/vrml/xml_markup.hpp"

namespace cadnurbs {

namespace {

const char* const kNodeName = "NurbsPositionInterpolator";

double rounded(double value, double tolerance) {
  return std::stod(format_number(value, NumberPrecision{tolerance, 0}));
}

std::string numbers(const FieldValue& value, double tolerance) {
  std::string out;
  append_numeric_value(out, value, NumberPrecision{tolerance, 0});
  return out;
}

// Where the start tag that opens at `begin` ends (one past its '>'), quotes honoured.
size_t start_tag_end(const std::string& text, size_t begin) {
  char quote = 0;
  for (size_t i = begin; i < text.size(); ++i) {
    const char c = text[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '>') {
      return i + 1;
    }
  }
  throw std::runtime_error("a start tag is not terminated");
}

std::string classic_declared(const std::string& text, VrmlEncoding encoding, const std::string& protos_url) {
  const size_t header_end = text.find('\n');
  if (header_end == std::string::npos || text.compare(0, 1, "#") != 0)
    throw std::runtime_error("the file has no header line");
  ClassicTokenizer tokens(text);
  ClassicToken previous;
  size_t profile_end = 0;  // past the PROFILE statement's name, if there is one
  for (ClassicToken token = tokens.next(); token.kind != ClassicToken::Kind::end; token = tokens.next()) {
    if (previous.kind == ClassicToken::Kind::word) {
      if ((previous.text == "PROTO" || previous.text == "EXTERNPROTO") && token.text == kNodeName) return text;
      if (previous.text == "PROFILE") {
        if (token.text == "Full") return text;
        profile_end = token.end;
      }
      if (previous.text == "COMPONENT" && token.text.rfind("NURBS:", 0) == 0) return text;
    }
    previous = std::move(token);
  }
  if (encoding == VrmlEncoding::x3d_classic) {
    if (profile_end) return text.substr(0, profile_end) + "\nCOMPONENT NURBS:1" + text.substr(profile_end);
    return text.substr(0, header_end + 1) + "COMPONENT NURBS:1\n" + text.substr(header_end + 1);
  }
  for (const ProtoDefinition& proto : nurbs_protos())
    if (proto.name == kNodeName)
      return text.substr(0, header_end + 1) + externproto_declaration(proto, protos_url) + text.substr(header_end + 1);
  throw std::runtime_error("the PROTO library has no PROTO NurbsPositionInterpolator");
}

std::string xml_declared(const std::string& text) {
  const XmlElement root = parse_xml_markup(text, "the file");
  if (root.name != "X3D") throw std::runtime_error("the root element is not <X3D>");
  if (const XmlAttribute* profile = root.attribute("profile"); profile && profile->value == "Full") return text;
  const std::string component = "<component name='NURBS' level='1'/>";
  for (const XmlElement& child : root.children) {
    if (child.name != "head") continue;
    for (const XmlElement& c : child.children)
      if (c.name == "component" && c.attribute("name") && c.attribute("name")->value == "NURBS") return text;
    const size_t head_end = start_tag_end(text, child.begin);
    if (head_end == child.end && text.compare(head_end - 2, 2, "/>") == 0)  // <head/>
      return text.substr(0, child.begin) + "<head>" + component + "</head>" + text.substr(child.end);
    return text.substr(0, head_end) + "\n" + component + text.substr(head_end);
  }
  const size_t x3d_end = start_tag_end(text, root.begin);
  return text.substr(0, x3d_end) + "\n<head>" + component + "</head>" + text.substr(x3d_end);
}

}  // namespace

std::string nurbs_position_interpolator_text(const NurbsCurve& curve, const std::string& def_name,
                                             VrmlEncoding encoding, const NurbsTolerances& tolerances,
                                             const std::string& container_field) {
  if (curve.is_rational()) throw std::invalid_argument("NurbsPositionInterpolator text: the curve is rational");
  const std::string knots = numbers(MFFloat{curve.knots}, tolerances.knot);
  const std::string points = numbers(MFVec3f{curve.points}, tolerances.control_point);
  const std::string order = std::to_string(curve.order);
  if (encoding == VrmlEncoding::x3d_xml) {
    std::string out = std::string("<") + kNodeName;
    if (!def_name.empty()) out += " DEF='" + xml_escaped(def_name) + "'";
    if (!container_field.empty()) out += " containerField='" + xml_escaped(container_field) + "'";
    return out + " order='" + order + "' knot='" + knots + "'><Coordinate containerField='controlPoint' point='" +
           points + "'/></" + kNodeName + ">";
  }
  std::string out = def_name.empty() ? std::string() : "DEF " + def_name + " ";
  out += std::string(kNodeName) + "{";
  if (encoding == VrmlEncoding::vrml97)
    return out + "dimension " + std::to_string(curve.count()) + " order " + order + " knot[" + knots + "] keyValue[" +
           points + "]}";
  return out + "order " + order + " knot[" + knots + "] controlPoint Coordinate{point[" + points + "]}}";
}

NurbsCurve as_written(const NurbsCurve& curve, const NurbsTolerances& tolerances) {
  NurbsCurve out = curve;
  for (double& knot : out.knots) knot = rounded(knot, tolerances.knot);
  for (Eigen::Vector3d& point : out.points)
    for (int c = 0; c < 3; ++c) point[c] = rounded(point[c], tolerances.control_point);
  return out;
}

std::string with_nurbs_interpolator_declared(const std::string& text, VrmlEncoding encoding,
                                             const std::string& protos_url) {
  if (encoding == VrmlEncoding::x3d_xml) return xml_declared(text);
  return classic_declared(text, encoding, protos_url);
}

}  // namespace cadnurbs
