#pragma once
// Steps 3 to 5 of tessellate_to_deviation (see its header): one face's mesh from its grid and its loop
// points (internal).
//
// In: a face with its grid (step 1) and loop points (step 2), and D. Out: Face::mesh, triangles counter-
// clockwise seen along Su x Sv with per-corner normals; loop points with one node are one mesh vertex,
// and triangles collapsed onto one vertex (at a pole) are dropped. The report gets the triangle count,
// the largest certified bound and the triangles left uncertified.
//  3. The loop points (collapsed runs split to the grid's resolution) are the constraints of a Delaunay
//     triangulation of the domain (DomainTriangulation, scaled so grid cells are square); grid points
//     inside the loops (even-odd) and not within 0.35 of a cell of a loop are added.
//  4. Every triangle is certified (certify_triangle). A failing one is refined: the midpoint of the side
//     where the error peaks, the point where it peaks, or the middle of its cut along a C0 knot line is
//     inserted; a collapsed boundary side is split (its new vertex on the same node). A triangle below
//     1e-9 of the domain, or one whose boundary side is itself off by more than D, is given up and
//     counted as uncertified; so is whatever is left after 200 rounds or a budget of vertices.
//  5. Points go to 3D with per-corner normals from the surface (stepping off poles: normal_at).
// Throws GeometryError (the face's name) for a loop of fewer than 3 distinct points, a loop that bounds
// no area, or one that leaves the surface's domain by more than 1e-2 of it (points less far out are
// moved onto the domain's edge, where the surface is clamped anyway).
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/tessellation/tessellation_face.hpp"

namespace cadnurbs::tessellation {

void mesh_face(Face& face, double max_deviation, TessellationReport& report);

}  // namespace cadnurbs::tessellation
