#pragma once
// fit-path's work on one VRML97 / X3D text: every PositionInterpolator that can be rewritten becomes a
// NurbsPositionInterpolator fitted within a deviation (analysis/fitting/fit_position_path), written in place of
// the old node (formats/vrml/nurbs_interpolator_text); every other byte of the text stays as it was.
// DEF names are kept, so ROUTEs to set_fraction and from value_changed still connect.
//
// Left as they are, each with its reason in the account:
//   - OrientationInterpolators: X3D's NurbsOrientationInterpolator outputs the rotation that takes +Z
//     to the curve's tangent, which cannot hold a roll about the path, and VRML97 has no such node;
//   - interpolators that find_interpolators marks unconvertible (IS fields, metadata, children);
//   - paths the fit refuses (a jump, keys outside [0, 1]) or that would not get smaller.
// An X3D XML USE of a rewritten interpolator is renamed with it.
#include <string>
#include <vector>

#include "formats/vrml/vrml_write_options.hpp"

namespace cadnurbs {

struct PathAccount {
  std::string type;       // PositionInterpolator or OrientationInterpolator
  std::string def_name;
  int line = 0;
  int keys = 0;
  bool converted = false;
  int control_points = 0;   // converted: of the curve
  int order = 0;
  double max_error = 0;     // converted: bound on the written curve's distance from the path
  size_t bytes_before = 0, bytes_after = 0;  // the node's text
  std::string left_because; // not converted: why
};

struct PathRewrite {
  std::string text;                  // the rewritten file (the input's text when nothing was converted)
  std::vector<PathAccount> accounts; // one per interpolator, in file order (XML USEs left out)
};

// Throws FileError "<name_for_errors>: line N: <reason>" when the text cannot be read, and
// std::invalid_argument for a deviation that is not > 0.
PathRewrite fit_paths_in_text(const std::string& text, VrmlEncoding encoding, double deviation,
                              const std::string& protos_url, const std::string& name_for_errors);

}  // namespace cadnurbs
