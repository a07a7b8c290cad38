#pragma once
// Rhino's SubD (ON_SubD) as the control net the user edits: level 0's vertices, edges and faces as a
// SubdControlNet, plus the limit surface points Rhino cached at its vertices. Later subdivision levels,
// texture and symmetry data are stepped over by their chunk lengths.
//
// Layout (facts from openNURBS's opennurbs_subd_archive.cpp): a byte (1: a SubD follows), then a
// versioned anonymous chunk 1.x (level count, three maximum ids, a bounding box, one versioned anonymous
// chunk 1.x per level). A level holds its index, three bytes, the control net's box, four archive id
// bounds (vertices [b0, b1), edges [b1, b2), faces [b2, b3)) and then the components in that order, each
// written in place (no chunk): ids and level, its tag and counts, and references as (archive id, flag
// byte). A face lists its edges; a flag's bit 0 says the face runs along the edge from its second vertex
// to its first. Archive version 60 ends each component with a zero byte; 70 adds size-prefixed
// "additions" (0 absent, 254 an anonymous chunk, 255 the end, else that many bytes), which are skipped.
#include <Eigen/Core>
#include <vector>

#include "core/subd_control_net.hpp"
#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

// A point of Rhino's limit surface that the file caches at a level-0 vertex (ON_SubDSectorSurfacePoint):
// where the surface passes for that control point and its normal there, in the file's unit. At a vertex
// with several sectors (a crease) the normal is the first sector's (openNURBS writes that sector's values
// for every sector); the position is the same for all.
struct SubdLimitPoint {
  int point = 0;  // index into SubdControlNet::points
  Eigen::Vector3d position;
  Eigen::Vector3d normal;
};

struct RhinoSubd {
  // Faces in the file's order, their points in the order the face runs along its edges; crease edges are
  // the edges tagged Crease (SmoothX and Smooth are smooth); corner_points the vertices tagged Corner.
  SubdControlNet net;
  std::vector<SubdLimitPoint> limit_points;  // in vertex order; only the vertices the file has one for
};

// Reads an ON_SubD's class data (the reader is inside its TCODE_OPENNURBS_CLASS_DATA chunk). A file's
// empty SubD (first byte 0) comes back empty. Throws ArchiveError "<file>: chunk ...: ON_SubD: <reason>"
// on an archive version other than 60 or 70 (80 adds semi-sharp creases the control net cannot carry),
// a chunk version other than 1.x, a first level that is not level 0, component counts that cannot fit
// in the chunk (checked before allocating), a component whose archive id or level is not the next one
// expected, a reference outside its component range, an edge without two vertices, a face whose edges
// do not join end to end, an unknown tag, and a net core's validate() refuses.
RhinoSubd read_subd(ArchiveReader& reader);

}  // namespace cadnurbs::rhino
