#pragma once
// ON_Brep's class data as Rhino 2 wrote it (chunk version 2.x, the legacy trimmed-surface collection that openNURBS's
// ON_Brep::ReadOld200 reads; facts from opennurbs_brep_io.cpp), read into the RhinoBrep that the version 3 reader
// (brep_object.hpp) makes.
//
// Layout (integers int32, flags uint8, points 3 doubles):
//   counts: faces, edges, loops, trims (each >= 1); an outer flag; the bounding box (2 points).
//   trims' 2D curves, one per trim in trim order, then edges' 3D curves, one per edge, each as ON_PolyCurve class
//     data with no object wrapper: its version byte, segment count, 2 reserved ints, a bounding box, an int32 count of
//     segment parameters and the doubles, then each segment as a nested object.
//   surfaces, one per face in face order, each as ON_NurbsSurface class data (no object wrapper).
//   faces: per face its legacy index, obsolete material index, reversed flag (m_bRev), a face type, its bounding box,
//     a loop count (>= 1), then per loop its legacy index, type (0 outer, 1 inner, -1 slit), parameter box
//     (4 doubles), a trim count (>= 1), then per trim its index (the running trim number), its twin's index (-1: none),
//     a flag (the trim owns its edge), its edge index, reversed-against-edge, continuity and monotonicity flags, its
//     3D tolerance and its 2D tolerance (doubles).
//   per face a flag and, when non-zero, its render mesh object; from minor version 1 on the same for analysis meshes.
//     The class data chunk ends there (openNURBS tolerates a failure in the meshes).
//
// Out (see brep_object.hpp): face i is surface i trimmed by its loops; trim n uses all of 2D curve n (the polycurve
// joined into one NURBS: a trim needs its locus only); an edge index outside the 3D curves means no edge (a singular
// trim), as in openNURBS; edge tolerances are the largest 3D tolerance of the edge's trims, a loop closes within its
// trims' 2D tolerance (what openNURBS's SetTolsFromLegacyValues rebuilds). The twin indices are not needed: every mated
// trim of Rhino 2's files carries its edge index itself. The 3D curves are stepped over (faces carry the geometry); the
// render meshes are kept when they read.
//
// A 2D curve or a surface that cannot be converted (e.g. a polycurve whose parameters do not increase) leaves its face
// out, in skipped_faces with the reason, like a face whose loops do not close. Refused with ArchiveError (file,
// innermost chunk, "Brep (Rhino 2 layout): <reason>"): a count below 1 or past the chunk, more trims in the loops than
// the trim count, an edge index out of range on a trim that owns its edge (all refused by openNURBS too), a record past
// the chunk. A trim's written index out of step with the running number is let through (openNURBS only reports it; the
// running number picks the curve).
#include "formats/3dm/archive_reader.hpp"
#include "formats/3dm/brep_object.hpp"

namespace cadnurbs::rhino {

// The reader stands inside an ON_Brep's TCODE_OPENNURBS_CLASS_DATA chunk, after its version byte (major 2). What
// follows the records (analysis meshes, the chunk's CRC) is left to the caller's end_chunk.
RhinoBrep read_brep_v2_layout(ArchiveReader& reader);

}  // namespace cadnurbs::rhino
