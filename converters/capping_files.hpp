#pragma once
// Writing one capping in every sample format; shared by `cadnurbs capping` and `cadnurbs demo`.
#include <string>
#include <vector>

#include "samples/capping.hpp"

namespace cadnurbs {

// The extensions a capping is written in: the formats of file_formats() marked in_samples (NURBS as
// .wrl, .x3dv, .x3d, .step, .iges; triangles as .stl).
std::vector<std::string> capping_extensions();

// Writes `capping` to `path`: NURBS, or for a format that holds meshes only the thesis STL rule.
// `with_lids` false leaves the handrail connections open (for viewers that ignore trimming).
void write_capping(const CappingDefinition& capping, const std::string& path, double max_chord_deviation,
                   bool with_lids = true);

// Writes DIR/<name><ext> for every extension; returns the paths written.
std::vector<std::string> write_capping_set(const CappingDefinition& capping, const std::string& dir,
                                           double max_chord_deviation);

}  // namespace cadnurbs
