#pragma once
// Sewing: which boundary pieces of different faces are one model edge, recovered from geometry alone,
// for scenes read from files that name no edges (VRML/X3D NURBS, the compact writer's polygons). The
// result carries the shared-edge identities (TrimEdgeRef) the STEP path gets from the B-rep, so that
// tessellate_to_deviation meshes it watertight. (OCCT's BRepBuilderAPI_Sewing does this for B-reps;
// this works on core types.)
//
// In:  a scene; tolerances (model units): `first`, how far apart two boundary curves may lie and still be
//      one edge (callers derive it from the precision the file was written with), and `largest`, up to
//      which the pieces still open afterwards are matched among themselves (gaps of the source model).
// Out: the scene in world coordinates (flatten_transforms); every polygon of a polygon set (a PolygonMesh,
//      or a TriangleMesh without normals: how the readers return the compact writer's planar faces) a
//      planar trimmed surface of its own (planar_polygon_surface; same name and colour); every untrimmed surface
//      trimmed by its domain rectangle; every trimming loop cut into pieces that run from model vertex
//      to model vertex, each with a TrimEdgeRef: one edge id for pieces whose 3D images coincide within
//      `tolerance`, -1 for a piece nothing else runs along (an open boundary) or that collapses to a
//      point (a pole). Meshes with normals (fallen-back faces, tessellations) and curves pass through.
// Faces are sewn within their group only: the nearest named node above them (a solid or part as the
// source named it) with the unnamed nodes below it, so that touching parts of an assembly stay apart.
// Method:
//  1. Pieces: NURBS trimming curves as they are; polylines cut at every point, since the compact writer
//     joins runs of straight edges into one polyline. 3D images sampled 8 times per knot span of the
//     piece and per patch of the surface it crosses.
//  2. Model vertices: piece ends closer than `tolerance` are one vertex (grid hashing, transitive).
//  3. A vertex within `tolerance` of a piece's interior (Newton on the piece's 3D image from the
//     nearest point of its samples) cuts the piece there (split_curve): a polygon side along which the
//     neighbour has two edges.
//  4. Pieces with the same two end vertices are one edge when every sample of each lies within
//     `first` of the other's 3D image (same projection). Faces that only touch at a point, or run
//     along each other further apart than `largest`, share no such pair and are not sewn.
//  5. The pieces still open repeat steps 2 and 4 among themselves at 10, 100, ... times `first`, up to
//     `largest` (no cuts): a STEP file written with a tolerance of 0.01 mm has gaps that wide.
//  6. An edge found on more than two pieces is split by solid (faces joined by the edges of exactly two
//     pieces): parts of an assembly whose faces coincide keep an edge each, as their B-reps do. Pieces
//     the split leaves alone (copies of one solid at one place) are paired one way with the other.
// The cuts are exact (the shape of every loop is unchanged); nothing moves.
#include "core/scene.hpp"

namespace cadnurbs {

struct SewingTolerance {
  double first = 0;
  double largest = 0;
};

struct SewingReport {
  int faces = 0;              // trimmed surfaces after polygons became faces
  int polygon_faces = 0;      // of which were polygons of polygon meshes
  int dropped_polygons = 0;   // polygons narrower than the tolerance (slivers: nothing to mesh)
  long pieces = 0;            // boundary pieces after cutting
  long shared_edges = 0;      // edge ids given: groups of two or more coinciding pieces
  long sewn_pieces = 0;       // pieces that got an edge id
  long open_pieces = 0;       // pieces that run along nothing else (the model's open boundary)
  double open_length = 0;     // their length (of their sample polygons)
  long point_pieces = 0;      // pieces whose 3D image is a point (poles)
  long cuts = 0;              // pieces cut at a vertex of another face (step 3)
  double widest_gap = 0;      // the widest tolerance of step 5 that matched pieces (0: none needed)
};

// The tolerances for a file read back and meshed at D: first ten times the precision cadnurbs writes
// coordinates with by default (1e-6 of the bounding-box diagonal), largest D/4, so that every sewn edge
// lies within D of both its faces (the tessellator certifies it on each) and faces 10 D apart are never
// sewn. (first is D/4 too when that is smaller.)
SewingTolerance sewing_tolerance(double bounding_box_diagonal, double max_deviation);

// Refuses (std::invalid_argument) tolerances that are not positive numbers with largest >= first.
Scene sew_faces(const Scene& scene, const SewingTolerance& tolerance, SewingReport* report = nullptr);

}  // namespace cadnurbs
