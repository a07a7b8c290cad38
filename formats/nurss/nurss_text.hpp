#pragma once
// A quadratic NURSS control mesh as a small text file (docs/nurss.md): the header line, the length
// unit, one line per vertex (x y z w: the Euclidean point and its weight), one line per face (its corner
// indices, counter-clockwise from outside), the non-zero face labels, one line per face with the knot
// intervals its corners hold on its sides, and the intervals of sides no face has (open meshes only).
//
// Why the intervals go by face: every directed side a→b of a manifold mesh belongs to one face, and
// d(a→b) (nurss_mesh.hpp) is the value a holds on that side; listing them in the face's corner order
// gives each (vertex, outgoing edge) its value with no index at all, so the file holds exactly the
// thesis's count (4 floats per control point + one per outgoing edge; nurss_storage.hpp).
//
// This lives in analysis/nurss beside NurssMesh rather than in formats/: formats see only core, and the
// mesh type is analysis's.
#include <string>

#include "core/nurss_mesh.hpp"
#include "core/number_format.hpp"
#include "core/scene.hpp"

namespace cadnurbs {

// The text of `mesh` in `unit`. Numbers are written with `precision` (default: the shortest text that
// reads back as the same double, so a round trip is bit-exact). Refuses (GeometryError, via validate)
// a mesh with unset intervals or bad weights.
std::string write_nurss_text(const NurssMesh& mesh, const LengthUnit& unit = {}, const NumberPrecision& precision = {});

// The mesh in `text`; its unit into `*unit` when given. Refuses (FileError "<name>: line <n>: <reason>",
// one line) a wrong header, a malformed or missing line, a count larger than the lines left, an index
// out of range, a non-finite number, a weight <= 0, a negative interval, a face the mesh refuses (or of
// more than 4,096 corners), trailing text, and a mesh that validate refuses (an interval left unset:
// "<name>: at the end: NURSS mesh: <reason>").
NurssMesh read_nurss_text(const std::string& text, const std::string& name, LengthUnit* unit = nullptr);

}  // namespace cadnurbs
