#pragma once
// A small XML reader for what X3D files use: the XML declaration, processing instructions, DOCTYPE (with
// an internal subset), comments, elements with single- or double-quoted attributes, the five named
// entities and numeric character references. Character data between elements is ignored;
// the text of CDATA sections (a Script's source) is kept. Not a general XML parser (no namespaces, no entity declarations).
#include <string>
#include <vector>

namespace cadnurbs {

struct XmlAttribute {
  std::string name, value;
  int line = 0;
};

struct XmlElement {
  std::string name;
  std::vector<XmlAttribute> attributes;
  std::vector<XmlElement> children;
  std::string cdata;  // the text of the CDATA sections among its children
  int line = 0;
  size_t begin = 0, end = 0;  // the element's bytes in the text, from '<' to past its closing '>'

  // The attribute called `n`, or null.
  const XmlAttribute* attribute(const std::string& n) const;
};

// The root element of `text`, with line numbers. Throws FileError "<name_for_errors>: line N: <reason>".
XmlElement parse_xml_markup(const std::string& text, const std::string& name_for_errors);

}  // namespace cadnurbs
