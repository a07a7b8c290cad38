#pragma once
// Reading one openNURBS object (the TCODE_OPENNURBS_CLASS chunk WriteObject writes: class id, class data,
// user data, end) and converting it to core geometry. One table maps class ids to readers
// (rhino_object.cpp); every class id cadnurbs does not read comes back as Unsupported with its name.
#include <string>
#include <variant>

#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"
#include "core/triangle_mesh.hpp"
#include "formats/3dm/archive_reader.hpp"
#include "formats/3dm/brep_object.hpp"
#include "formats/3dm/subd_object.hpp"

namespace cadnurbs::rhino {

struct Unsupported {
  std::string class_name;  // openNURBS's name when the id is known (e.g. "ON_SubD"), else the id's text
};

// Curves come back as NurbsCurve (dimension 2 or 3; a Brep's 2D trims are dimension 2), surfaces as
// NurbsSurface, Breps and Extrusions as RhinoBrep, meshes as TriangleMesh, SubDs as RhinoSubd (level 0's
// control net and the limit points the file caches).
using RhinoGeometry = std::variant<Unsupported, NurbsCurve, NurbsSurface, RhinoBrep, TriangleMesh, RhinoSubd>;

// Reads the TCODE_OPENNURBS_CLASS chunk at the reader's offset and everything in it; on return the reader
// is after it. Throws ArchiveError on a malformed chunk or class data.
RhinoGeometry read_object(ArchiveReader& reader);

// The openNURBS class name for a class id ("ON_NurbsCurve"), or "" when the table does not know it.
std::string class_name(const Uuid& class_id);

}  // namespace cadnurbs::rhino
