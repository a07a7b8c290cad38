#pragma once
// A Rhino Brep (ON_Brep) or Extrusion (ON_Extrusion) as trimmed NURBS faces that keep the Brep's edge
// identity, so that faces sharing an edge mesh watertight once the scene numbers the edges.
#include <optional>
#include <string>
#include <vector>

#include "core/triangle_mesh.hpp"
#include "core/trimmed_surface.hpp"
#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

struct RhinoBrep {
  // One per Brep face, in the file's order. Loops follow the VRML/X3D rule (outer counter-clockwise,
  // holes clockwise, a reversed face's surface flipped so that its normal points out). A trim on a Brep
  // edge carries TrimEdgeRef{edge index in this Brep, reversed}; a singular trim (a pole) carries -1.
  std::vector<TrimmedSurface> faces;
  int edge_count = 0;  // TrimEdgeRef::edge < edge_count
  // Per edge, the file's tolerance: the faces that share the edge meet there within it (0: exactly;
  // Rhino writes the largest distance it found between the edge and its trims' images).
  std::vector<double> edge_tolerances;
  // Per entry of `faces`, its 0-based index among the file's faces (they differ once a face is skipped).
  std::vector<int> face_indices;
  // Faces that could not be read or converted, each "face N: reason" (N 1-based); the other faces are kept.
  std::vector<std::string> skipped_faces;
  std::vector<int> skipped_face_indices;  // per entry of skipped_faces, its index among the file's faces
  // (Added by the lead.) The render mesh Rhino stored with each Brep face (ON_Brep chunk version 3.1 on:
  // an anonymous chunk after the faces, one byte per face, then the ON_Mesh object when the byte is 1),
  // indexed like the file's faces (face_indices, skipped_face_indices); empty when the file stores none.
  // Used to check trimmed areas and to mesh a face that cannot be built.
  std::vector<std::optional<TriangleMesh>> render_meshes;
};

// Reads an ON_Brep's class data (the reader is positioned inside its TCODE_OPENNURBS_CLASS_DATA chunk).
// Throws ArchiveError on a malformed Brep (index out of range, counts past the chunk).
RhinoBrep read_brep(ArchiveReader& reader);

// Reads an ON_Extrusion's class data and builds its faces (side faces from the profiles swept along the
// path, caps as trimmed planes when the profiles are closed and capped).
RhinoBrep read_extrusion(ArchiveReader& reader);

}  // namespace cadnurbs::rhino
