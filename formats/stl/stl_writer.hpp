#pragma once
// Writing a TriangleMesh as an STL file, ASCII or binary.
#include <string>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

enum class StlEncoding { binary, ascii };

// Takes a mesh, an encoding and a solid name; returns the bytes of the STL file.
// - One facet per triangle. Coordinates are rounded to float32 (what STL stores). The facet
//   normal is facet_normal() of the rounded corners (zero for a degenerate triangle);
//   mesh.corner_normals are not written (an STL facet has one normal, implied by its corners).
// - Binary: 80-byte header "cadnurbs <solid_name>" cut to 80 bytes and padded with spaces (it never
//   starts with "solid", so no reader takes it for ASCII), uint32 count, then float32 values and a
//   zero attribute, all little-endian.
// - ASCII: "solid <name>" ... "endsolid <name>", numbers as %.9g of the float32 value so that
//   reading them back gives the same float32. Control characters in the name become spaces.
// Refuses (GeometryError, entity = solid_name): a mesh that fails validate(), a coordinate that
// does not fit float32 (naming the triangle), more than 2^32 - 1 triangles in binary.
std::string format_stl(const TriangleMesh& mesh, StlEncoding encoding, const std::string& solid_name);

// Writes format_stl(mesh, encoding, solid_name) to `path` through a temporary file and a rename.
// Refuses as format_stl; throws FileError when the file cannot be written.
void write_stl(const std::string& path, const TriangleMesh& mesh, StlEncoding encoding, const std::string& solid_name);

}  // namespace cadnurbs
