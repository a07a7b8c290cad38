#pragma once
// A triangle mesh as Draco bytes (Google's mesh codec, Debian's libdraco 1.5.5) and back, in memory:
// Draco's own STL reader misreads STL files (DESIGN.md), so meshes never go through a file here.
// Positions and triangles only; normals are not stored.
//
// Draco's position quantisation (read from its 1.5.5 source, all in 32-bit floats): positions become
// floats; the grid origin is the per-axis minimum of those floats; the step is the LARGEST axis extent
// divided by 2^bits - 1 (one cubic grid for all three axes; extent 1 when all points coincide);
// q = floor((p - origin) * (2^bits - 1) / extent + 0.5) and the decoder gives
// origin + q * (extent / (2^bits - 1)). draco_quantised_positions replays this arithmetic so that the
// displacement of every vertex can be known exactly without matching decoded vertices to originals.
#include <string>
#include <vector>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// Draco bytes of `mesh` (positions and triangles). position_bits: quantisation bits per axis, 1..30
// (above 24 the float positions limit the precision anyway). speed: Draco's encoder and decoder speed
// option, 0 (best compression) .. 10 (fastest; 10 stores connectivity sequentially, every other speed
// uses Edgebreaker, which reorders vertices and triangles and drops triangles with a repeated corner
// index and vertices no triangle uses). Throws GeometryError (entity "Draco mesh") for an invalid
// mesh, bits or speed out of range, or when Draco refuses the mesh (its reason quoted).
std::string encode_draco_mesh(const TriangleMesh& mesh, int position_bits, int speed);

// The mesh in Draco `bytes` (positions as decoded, in Draco's vertex and triangle order, no normals).
// Throws FileError "<name>: <reason>" for bytes Draco cannot decode (Draco's reason quoted), a mesh
// without positions, or decoded indices or positions that are out of range or not finite.
TriangleMesh decode_draco_mesh(const std::string& bytes, const std::string& name);

// Where Draco's quantisation at `position_bits` puts each vertex of `mesh` (same order): bit for bit
// the positions decode_draco_mesh returns for those vertices.
std::vector<Eigen::Vector3d> draco_quantised_positions(const TriangleMesh& mesh, int position_bits);

}  // namespace cadnurbs
