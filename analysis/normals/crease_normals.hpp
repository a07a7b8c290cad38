#pragma once
// Smoothing normals with sharp creases kept: VRML's creaseAngle on an indexed triangle mesh.
#include "analysis/mesh/side_partners.hpp"
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// What with_crease_normals found.
struct CreaseNormalsReport {
  int distinct_normals = 0;    // corner groups sharing one normal (a vertex with k sharp sectors counts k)
  int smooth_edges = 0;        // two faces, opposite directions, dihedral angle below the crease angle
  int sharp_edges = 0;         // two faces, opposite directions, angle at or above the crease angle
  int boundary_edges = 0;      // one face
  int non_manifold_edges = 0;  // three or more faces
  int inconsistent_edges = 0;  // two faces running the edge the same way (orientation flips there)
};

// Normals shared by corners: corner k of triangle t has normals[corner_normal[3t + k]].
struct CornerNormals {
  std::vector<Eigen::Vector3d> normals;  // unit, or zero at a zero-area triangle
  std::vector<int> corner_normal;        // 3 per triangle
};

// Takes a welded mesh (shared vertices; see weld_vertices) and a crease angle in radians; returns one
// normal per group of corners that share it, and each corner's group.
// Around each vertex, two faces that share an edge are joined when the angle between their face
// normals is below the crease angle; joins chain around the vertex, and each chain of corners gets
// one normal: the sum of its faces' unit normals weighted by the corner angles, normalised (weighting
// by angle makes the result independent of how a face is split into triangles). Faces across an
// edge at or above the crease angle, a boundary edge, an edge with three or more faces, or an edge
// where the two faces' orientations disagree, are not joined there (this is the meaning of creaseAngle
// in VRML97 and X3D; orientation is another step's job). A zero-area triangle joins nothing and keeps
// a zero normal; a chain whose weighted sum cancels gets each corner's own face normal (one entry per
// corner then). Normals are numbered in order of their groups' first corners.
// Memory: besides the result (a normal per group, an int per corner), an int per corner and the side
// partners while the groups are formed; no per-corner vectors (on 2 million triangles those would be 144 MB).
// Time: the edges' angles and the groups' sums are shared out to worker_threads() threads, each sum made
// by one thread in corner order, so the result does not depend on the thread count.
// `partners`, when given, must be side_partners(welded) (orient_faces hands them out with its result);
// otherwise they are made here.
// Refuses (std::invalid_argument) a negative or non-finite angle, and partners not of three sides per
// triangle; validate()s the mesh.
CornerNormals crease_normals(const TriangleMesh& welded, double crease_angle_radians,
                             CreaseNormalsReport* report = nullptr, const SidePartners* partners = nullptr);

// The same normals spread to the corners: returns `welded` (by value, so that a caller done with it
// can std::move it in) with corner_normals[3t + k] = normals[corner_normal[3t + k]].
TriangleMesh with_crease_normals(TriangleMesh welded, double crease_angle_radians,
                                 CreaseNormalsReport* report = nullptr, const SidePartners* partners = nullptr);

}  // namespace cadnurbs
