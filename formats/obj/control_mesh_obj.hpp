#pragma once
// A Loop subdivision control mesh with its sharp-feature tags as a Wavefront OBJ file that viewers open as
// the control mesh: "v" positions, "f" triangles, crease edges as "l" polylines, tagged corners as one
// "p" element. The layout and its rules are in docs/control_mesh_obj.md.
#include <string>

#include "core/subdivision_control_mesh.hpp"

namespace cadnurbs {

// The file text: a first line "# cadnurbs Loop control mesh, format 1 ...", then every position in full
// (shortest text that reads back as the same double, "-0" kept), every triangle, the crease edges
// chained into as few "l" polylines as a greedy walk finds, and the corners on one "p" line.
// Refuses (GeometryError, entity "Loop control mesh") what the reader would refuse, so a written file
// always reads back: no triangles, a non-finite coordinate, an index out of range, a triangle using a
// vertex twice, a crease edge not written {a, b} with a < b, repeated, or not an edge of a triangle, a
// corner repeated.
std::string format_control_mesh_obj(const SubdivisionControlMesh& mesh);

// format_control_mesh_obj written atomically to `path` (FileError when it cannot be written).
void write_control_mesh_obj(const std::string& path, const SubdivisionControlMesh& mesh);

// Takes an OBJ file's text and the name to put in messages; returns its control mesh. Reads the files
// written above and any triangle-only OBJ (then with no tags):
// - "v x y z" (further values, such as colours, ignored); "f" with 3 corners written a, a/t, a/t/n or
//   a//n; "l" with 2 or more vertices (a or a/t), each consecutive pair a crease edge; "p" with 1 or
//   more vertices, each a corner. Indices are 1-based, or negative: relative to the vertices read so
//   far (-1 the last). A positive index may name a vertex defined further down.
// - vn, vt, vp, o, g, s, mg, usemtl, mtllib, usemap, maplib, lod, bevel, c_interp, d_interp, shadow_obj,
//   trace_obj, comments and blank lines are skipped.
// - crease_edges: {a, b} with a < b, sorted, duplicates dropped; corner_vertices sorted, duplicates
//   dropped; so meshes with the same tags compare equal element by element.
// Refuses (FileError "<name>: line <n>: <problem>", one line; "<name>: <problem>" for the whole file):
// a face with other than 3 corners (polygons are not triangulated: that would change the limit
// surface), a vertex with fewer than 3 coordinates, a number that does not parse or is not finite, an
// index that is 0, not an integer or out of range, a face using a vertex twice, a crease edge that is
// not an edge of any triangle, an element this reader does not know (curves and free-form surfaces
// would be lost), a cadnurbs header of another format version, and a file with no triangles.
SubdivisionControlMesh parse_control_mesh_obj(const std::string& text, const std::string& name_for_errors);

// parse_control_mesh_obj of the file at `path`, errors naming `path` (FileError also when unreadable).
SubdivisionControlMesh read_control_mesh_obj(const std::string& path);

}  // namespace cadnurbs
