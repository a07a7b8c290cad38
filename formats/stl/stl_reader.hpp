#pragma once
// Reading STL files, ASCII or binary (told apart by content), into a TriangleMesh.
#include <string>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

struct StlReadOptions {
  bool facet_normals = true;        // false: corner_normals left empty (for a caller that computes its own)
  bool merge_equal_points = false;  // true: corners with equal coordinates share one position (EqualPoints)
};

// Takes the path of an STL file; returns parse_stl of its bytes, errors naming `path`. A binary file is
// read a block at a time (its bytes are never all in memory at once); one of 2^17 facets or more is read
// in worker_threads() parts at once, each into its own table of equal points, and the parts joined in
// order: the same mesh, numbers and errors as read in one go.
// Throws FileError when the file cannot be read or is not valid STL (see parse_stl).
TriangleMesh read_stl(const std::string& path, StlReadOptions options = {});

// Takes the bytes of an STL file and the name to put in error messages; returns its triangles.
// - Binary when the size is exactly 84 + 50 * count (count = uint32 at byte 80), even if the
//   header starts with "solid". Otherwise ASCII: "solid" after optional whitespace, then facets;
//   keywords are case-insensitive; several solids in a row are concatenated.
// - Vertices are NOT welded: triangle t uses positions 3t, 3t+1, 3t+2, in file order; with
//   options.merge_equal_points, corners with bitwise-equal coordinates are one position, numbered in
//   order of first occurrence (weld_vertices then gives the same mesh as from the soup). Binary
//   coordinates are the float32 values widened to double; ASCII coordinates are the parsed
//   doubles (not rounded to float32).
// - corner_normals: empty when every facet normal in the file is zero (the file carries none) or
//   options.facet_normals is false;
//   otherwise three copies of each facet's normal, normalized; a facet whose normal is zero or not
//   finite gets facet_normal() of its corners instead (zero when degenerate).
// Refuses (FileError "<name>: <position>: <problem>", one line): an empty file; a truncated binary
// file (byte offset and triangle number); a binary file holding whole triangles but fewer than its
// count (both numbers); a binary size mismatch that is not ASCII STL either
// (the size it should have); an ASCII syntax error (line, facet number, expected and found
// token); a non-finite coordinate (triangle or facet number).
TriangleMesh parse_stl(const std::string& bytes, const std::string& name_for_errors, StlReadOptions options = {});

}  // namespace cadnurbs
