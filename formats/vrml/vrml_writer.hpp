#pragma once
// Writes a Scene as VRML97 (with the blaxxun/VRML97-amendment NURBS nodes, declared by EXTERNPROTO),
// X3D classic (.x3dv) or X3D XML (.x3d). The mapping is described in scene_to_nodes.hpp and
// geometry_to_nodes.hpp, the number precision in vrml_write_options.hpp and nurbs_tolerances.hpp.
#include <string>

#include "core/scene.hpp"
#include "formats/vrml/nurbs_protos.hpp"  // nurbs_protos_library(): to write next to VRML97 outputs
#include "formats/vrml/vrml_write_options.hpp"

namespace cadnurbs {

// The file text. Validates the scene first: throws GeometryError "<entity>: <reason>" for invalid
// geometry or a singular transform, std::runtime_error when VRML97 output needs a NURBS node the PROTO
// library lacks, std::invalid_argument for a negative tolerance or more than 17 significant digits.
std::string format_vrml(const Scene& scene, const VrmlWriteOptions& options);

// format_vrml written atomically to `path`, gzip'd when options.gzipped. Throws FileError "<path>: <reason>"
// for any of the above and for I/O failures.
void write_vrml(const std::string& path, const Scene& scene, const VrmlWriteOptions& options);

}  // namespace cadnurbs
