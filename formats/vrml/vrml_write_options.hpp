#pragma once
// What a VRML/X3D writer is asked for: encoding, control point convention, precision, camera, title.
#include <optional>
#include <string>

#include "core/tessellation_hints.hpp"
#include "core/trimmed_surface.hpp"
#include "formats/vrml/viewpoint.hpp"
#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

enum class VrmlEncoding { vrml97, x3d_classic, x3d_xml };

struct VrmlWriteOptions {
  VrmlEncoding encoding = VrmlEncoding::x3d_classic;
  // controlPoint as w·P (what the viewers expect, see DESIGN.md) or as Euclidean P.
  bool homogeneous_control_points = true;
  // Absolute, in model units, per coordinate of the evaluated geometry; 0: 1e-6 × the scene's
  // bounding-box diagonal. Weights, knots and trims get tolerances derived from it (nurbs_tolerances.hpp).
  double coordinate_tolerance = 0.0;
  // > 0: every number with this many significant digits (the CLI's --precision N), overriding the
  // tolerances; knot vectors still get more digits where fewer would merge or reorder knots.
  int significant_digits = 0;
  // VRML97 only: paste the PROTO definitions instead of EXTERNPROTO declarations.
  bool self_contained = false;
  // VRML97 only: where EXTERNPROTO declarations point after the URNs ("<protos_url>#<Name>").
  std::string protos_url = "cadnurbs-nurbs-protos.wrl";
  // The camera; empty: framing_viewpoint of the scene's bounding box.
  std::optional<Viewpoint> viewpoint;
  // WorldInfo title; empty: the root node's name, if any.
  std::string title;
  // Indented, one field per line (for people); false: the fewest bytes (for machines and the web).
  bool pretty = false;
  // Both set: every NURBS face gets the uTessellation / vTessellation / trimming-curve tessellation
  // counts with which a viewer that tessellates uniformly draws it within about `display_deviation`
  // (model units; the converter passes analysis/tessellation/plan_tessellation_hints, which the writer
  // may not call itself).
  double display_deviation = 0.0;
  TessellationHints (*tessellation_hints)(const TrimmedSurface& face, double deviation) = nullptr;
  // write_vrml: the file gzip'd (.wrz, .x3dvz, .x3dz), as browsers read it.
  bool gzipped = false;
};

// VRML97 for .wrl, X3D for both X3D encodings.
inline VrmlDialect dialect_of(VrmlEncoding encoding) {
  return encoding == VrmlEncoding::vrml97 ? VrmlDialect::vrml97 : VrmlDialect::x3d;
}

}  // namespace cadnurbs
