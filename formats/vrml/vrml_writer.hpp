#pragma once
// Writes a Scene as VRML97 (with the blaxxun/VRML97-amendment NURBS nodes, declared by EXTERNPROTO),
// X3D classic (.x3dv) or X3D XML (.x3d). The pipeline, one file per step:
//
//   Scene ──scene_to_nodes──> node graph (node_graph.hpp: Node, Field, DEF names)
//           └ geometry_to_nodes: one geometry node per Shape (NURBS, polygons, meshes), its numbers'
//             precision from nurbs_tolerances; tessellation hints when the options carry them
//         ──share_repeated_nodes──> repeated subtrees DEF'd once and USE'd
//         ──classic_encoding | xml_encoding──> text (node_text: numbers; world_info, viewpoint,
//             proto_library: header nodes and the VRML97 EXTERNPROTOs)
//         ──write_vrml──> file, atomically, gzip'd when asked (formats/common)
//
// Reading runs the other way: classic_parser | xml_parser -> node graph -> nodes_to_scene /
// nodes_to_geometry -> Scene (vrml_reader.hpp).
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
