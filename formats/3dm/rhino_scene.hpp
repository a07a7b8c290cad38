#pragma once
// A .3dm file as a cadnurbs Scene: one node per layer, one node per object under its layer, Breps and
// Extrusions as trimmed NURBS faces sharing scene-wide edge numbers, in millimetres.
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "formats/3dm/rhino_file.hpp"
#include "formats/3dm/subd_object.hpp"

namespace cadnurbs::rhino {

struct RhinoScene {
  Scene scene;  // millimetres; scene.source_unit is the file's unit system
  // In file order, each one line: the file's own warnings (objects skipped by class), then every face
  // that was left out ("object 3 'name' face 2: reason") or repaired ("object 3 'name' face 2: what").
  std::vector<std::string> warnings;
  // A Brep face that could not be a trimmed NURBS surface and is in the scene as the render mesh Rhino
  // stored with it ("face K (mesh)").
  struct MeshedFace {
    std::string object;  // "object N" or "object N 'name'"
    int face = 0;        // K, 1-based among the Brep's faces in the file
    std::string reason;
  };
  std::vector<MeshedFace> meshed_faces;
  int face_count = 0;     // Brep/Extrusion faces in the scene: trimmed NURBS + meshed_faces
  int skipped_faces = 0;  // Brep/Extrusion faces the file has that are not in the scene (no render mesh)
  // Scene-wide edges: TrimEdgeRef::edge < edge_count. Each Brep's edges are numbered after the previous
  // Brep's, so only faces of one Brep share an edge.
  int edge_count = 0;
  // Every SubD object, in file order, in millimetres. Its scene node (the same source_entity) holds no
  // shapes: the control net is turned into surfaces later.
  struct SubdObject {
    std::string source_entity;  // "object N", as its node's
    std::string object_label;   // "object N" or "object N 'name'"
    SubdControlNet net;
    // Rhino's limit surface at some control points, as the file caches it (see RhinoSubd); what the
    // surfaces made from `net` can be measured against. The file holds no render mesh of a SubD.
    std::vector<SubdLimitPoint> stored_limit_points;
  };
  std::vector<SubdObject> subd_objects;
};

// Takes a parsed file and the name to use for the root node (the file's stem). Returns its scene:
//  - root: name `root_name`; a child per layer that holds objects (name and colour of the layer), in
//    layer order; objects whose layer index is not in the table go to the root;
//  - per object a node (name: the object's name, source_entity "object N" with N its 0-based index in the
//    object table; colour: the object's own when its colour source is the object) holding its shapes:
//    one per Brep face ("face K", 1-based), or the one curve, surface or mesh; a SubD's node has none and
//    its net goes to subd_objects;
//  - lengths scaled from the file's unit to millimetres (in_unit), knots and trims untouched.
// Each face's loops go through repair_trimming_loops. A face that the Brep reader could not build or that
// repair refuses becomes Rhino's render mesh of it when the file stores one (meshed_faces), else it is
// left out with a warning (skipped_faces); the rest of the Brep and the file still convert.
RhinoScene scene_from_3dm(const Rhino3dmFile& file, const std::string& root_name);

// read_3dm_file(path), then scene_from_3dm with the file's stem. Throws ArchiveError/FileError (one line,
// naming the file, and for a broken archive the chunk's typecode and offset).
RhinoScene read_3dm(const std::string& path);

}  // namespace cadnurbs::rhino
