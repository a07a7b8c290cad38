#pragma once
// A NURBS curve as the text of one NurbsPositionInterpolator node, for a rewriter that replaces a
// PositionInterpolator in a file it otherwise leaves alone (fit-path), and the declarations the file
// then needs.
//   VRML97 (the blaxxun proposal, implemented by the PROTO library's NurbsPositionInterpolator):
//     DEF n NurbsPositionInterpolator{dimension N order k knot[...] keyValue[...]}
//   X3D classic: DEF n NurbsPositionInterpolator{order k knot[...] controlPoint Coordinate{point[...]}}
//   X3D XML: <NurbsPositionInterpolator DEF='n' order='k' knot='...'><Coordinate
//     containerField='controlPoint' point='...'/></NurbsPositionInterpolator>
// Only polynomial curves are written (no weight or keyWeight field), so the control points mean the
// same whether a reader takes them as Euclidean or as w·P.
#include <string>

#include "core/nurbs_curve.hpp"
#include "formats/vrml/nurbs_tolerances.hpp"
#include "formats/vrml/vrml_write_options.hpp"

namespace cadnurbs {

// The node's text, numbers within `tolerances` (curve_tolerances with Euclidean points). `container_field`
// (XML only) is written when not empty. Refuses (std::invalid_argument) a rational curve.
std::string nurbs_position_interpolator_text(const NurbsCurve& curve, const std::string& def_name,
                                             VrmlEncoding encoding, const NurbsTolerances& tolerances,
                                             const std::string& container_field = {});

// The curve a reader of that text gets back: every control point coordinate and knot rounded as written.
NurbsCurve as_written(const NurbsCurve& curve, const NurbsTolerances& tolerances);

// `text` (a whole file of `encoding`) with what NurbsPositionInterpolator needs declared, added once:
//   VRML97: the PROTO library's EXTERNPROTO NurbsPositionInterpolator (pointing at `protos_url`) after
//     the header line, unless the file already declares or defines that name;
//   X3D classic: "COMPONENT NURBS:1" after the PROFILE line, unless the profile is Full or a NURBS
//     component is declared;
//   X3D XML: <component name='NURBS' level='1'/> as the first element of <head> (a <head> is added
//     after the <X3D> start tag when there is none), under the same conditions.
// Throws std::runtime_error when the file has no header line (VRML97, X3D classic) or no <X3D> element.
std::string with_nurbs_interpolator_declared(const std::string& text, VrmlEncoding encoding,
                                             const std::string& protos_url);

}  // namespace cadnurbs
