#pragma once
// Stair cappings (seed 001, ch. 4): the whole handrail profile swept along a smooth path of lines
// and arcs, as one exact rational quadratic NURBS body, with the two handrail connections closed
// by planar lids trimmed by the profile (one trimming loop each, seed 001, 5.1).
#include <string>

#include "core/scene.hpp"
#include "core/triangle_mesh.hpp"
#include "samples/outline.hpp"

namespace cadnurbs {

struct CappingDefinition {
  std::string name;
  Outline path;          // smooth, in its plane (path.plane)
  Outline half_profile;  // from the top on the axis, through x > 0, to the bottom on the axis
};

// Parses and checks the two texts (see shapes/README.md). Throws std::runtime_error naming the file.
CappingDefinition parse_capping(const std::string& name, const std::string& path_text, const std::string& path_name,
                                const std::string& profile_text, const std::string& profile_name);

// The capping as a Scene: node `name` with shapes "body", "lid-start", "lid-end" (millimetres).
Scene capping_nurbs(const CappingDefinition& capping);

// The capping as triangles by the thesis's STL rule: lines kept straight, arcs divided so no chord
// lies farther than max_chord_deviation from its arc (path arcs measured at the profile's outermost
// offset); lids triangulated from the profile polygon. Where an arc of the path meets an arc of the
// profile the two chord errors add: the surface lies within 2 x max_chord_deviation of the mesh.
// `with_lids` false: the swept body alone (open at the handrail connections).
TriangleMesh capping_mesh(const CappingDefinition& capping, double max_chord_deviation, bool with_lids = true);

// Exact geometry for checks: the point on the swept surface at path arc-parameter and profile
// point, and the distance of any point to the exact swept body surface (not the lids).
double distance_to_swept_surface(const CappingDefinition& capping, const Eigen::Vector3d& point);

}  // namespace cadnurbs
