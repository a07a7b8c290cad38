#pragma once
// Rhino SubD objects (the reader's control nets) put into the scene as NURBS patches: the exact bicubic
// patches of the regular faces and the fitted ones near extraordinary points (analysis/subd_nurbs).
#include "formats/3dm/rhino_scene.hpp"
#include "formats/brep/brep_translation.hpp"

namespace cadnurbs {

// Takes the .3dm reader's SubD objects, the scene they belong to (out.scene, whose nodes carry their
// source_entity) and the fitted patches' deviation: `deviation` > 0, or 0 for 1e-4 of each SubD's box
// diagonal (a tenth of the default mesh deviation). Each object's node gets one shape per patch ("patch
// K", 1-based), numbered edges after out's (degenerated_edges grows, face_count counts the patches), and
// out.notes one line per object saying how many patches are exact and within what the fitted ones are.
// An object the conversion refuses is left out with a line in out.repairs naming it and the reason; the
// rest of the file converts.
void add_subd_objects_as_nurbs(const std::vector<rhino::RhinoScene::SubdObject>& objects, double deviation,
                               BrepTranslation& out);

}  // namespace cadnurbs
