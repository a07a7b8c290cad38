#pragma once
// Rhino 1's legacy polysurfaces (TCODE_LEGACY_SHL) and trimmed surfaces (TCODE_LEGACY_FAC) as RhinoBrep,
// the form ON_Brep's ReadV1_LegacyShellStuff / ReadV1_LegacyFaceStuff make of them (facts from
// openNURBS's opennurbs_archive.cpp).
//
// Layout (all integers int32 unless said):
//   shell stuff: outer flag, face count, bounding box (2 points), glue count n, n int16 "glue", then per
//     face a TCODE_LEGACY_FAC chunk holding a face stuff chunk.
//   face stuff: normal-flipped flag (0/1), face type, 2 * loop count + 1, bounding box (6 doubles), glue
//     count m, m int16, a TCODE_LEGACY_SRF chunk (surface, see legacy_nurbs.hpp), then per loop a
//     TCODE_LEGACY_BND chunk holding a loop stuff chunk.
//   loop stuff: trim count (>= 1), type (-1 slit, 0 outer, 1 inner), parameter box (4 doubles), then per
//     trim a TCODE_LEGACY_TRM chunk holding a trim stuff chunk.
//   trim stuff: a flag byte (bit 0: the trim owns a new edge, whose 3D curve follows its 2D curve; bit 1:
//     its mate is in the same face, a seam; bit 1 or 2: it has a mate), reversed-against-edge flag, two
//     legacy flags, 3D and 2D tolerances (doubles), the 2D curve (TCODE_LEGACY_CRV), then the edge's 3D
//     curve (TCODE_LEGACY_CRV) when bit 0 is set.
// A mate that does not own the edge gets its partner's: "glue" is a permutation pairing, in trim order,
// the seam trims of a face (face glue) or the mated non-seam trims of a shell (shell glue); openNURBS
// glues only when the count of such trims equals the glue count, and so does this reader.
//
// Out: one TrimmedSurface per face as brep_object.hpp describes (outer loops counter-clockwise, holes
// clockwise, a flipped face's surface transposed so its normal points out), each trim's edge as a
// TrimEdgeRef (a singular trim, at a pole, has none), edge tolerances the largest 3D tolerance of the
// edge's trims. The 3D edge curves are stepped over: the faces carry the geometry. No render meshes:
// V1 files store none with their surfaces.
//
// A face whose loops do not close within the trims' 2D tolerance (or 1e-9 of the surface's parameter
// size) or whose geometry core's validate() refuses is left out, in skipped_faces. Refused with
// ArchiveError (the innermost chunk and the reason): a record that runs past its chunk, a missing
// wrapped chunk, a flag or count openNURBS refuses, a curve or surface legacy_nurbs.hpp refuses.
#include "formats/3dm/archive_reader.hpp"
#include "formats/3dm/brep_object.hpp"

namespace cadnurbs::rhino {

// The reader stands at the start of a shell stuff chunk's body (TCODE_LEGACY_SHLSTUFF).
RhinoBrep read_legacy_shell(ArchiveReader& reader);

// The reader stands at the start of a face stuff chunk's body (TCODE_LEGACY_FACSTUFF): a one-face Brep.
RhinoBrep read_legacy_face(ArchiveReader& reader);

}  // namespace cadnurbs::rhino
