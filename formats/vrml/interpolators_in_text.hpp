#pragma once
// The keyframe interpolators of a VRML97, X3D classic or X3D XML text, with the bytes each node
// occupies, so that a rewriter (fit-path) can replace those nodes and pass every other byte through as
// it was. Only PositionInterpolator and OrientationInterpolator nodes are reported.
//
// Classic encodings: the text is read as tokens (strings and comments skipped), and a node is the type
// name followed by '{', with "DEF name" before it when there is one; a PROTO body's nodes are found too.
// XML: every element of that name (the file must pass xml_markup's reader).
//
// A node that cannot be rewritten is still reported, with `unconvertible` saying why: a field other
// than key and keyValue (X3D metadata, children), a field given by IS inside a PROTO body, an XML USE.
#include <string>
#include <vector>

namespace cadnurbs {

struct InterpolatorInText {
  std::string type;                 // "PositionInterpolator" or "OrientationInterpolator"
  std::string def_name;             // empty when the node is not DEF'd
  std::string container_field;      // XML only: the containerField attribute, if given
  std::string use_name;             // XML only: the element is a USE of this DEF name (no fields of its own)
  std::vector<double> key;
  std::vector<double> key_value;    // flat: 3 numbers per key (position) or 4 (axis x y z, angle)
  size_t begin = 0, end = 0;        // the node's bytes, "DEF name" included, [begin, end)
  int line = 0;
  std::string unconvertible;        // empty, or why the node must stay as it is
};

// In file order. Throws FileError "<name_for_errors>: line N: <reason>" for text the readers refuse
// (an unterminated string, malformed XML) and for a key or keyValue that holds something else than
// numbers.
std::vector<InterpolatorInText> find_interpolators(const std::string& text, bool xml,
                                                   const std::string& name_for_errors);

}  // namespace cadnurbs
