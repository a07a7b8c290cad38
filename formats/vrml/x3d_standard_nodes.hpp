#pragma once
// The nodes of the X3D 4.0 standard as data (x3d_standard_nodes.cpp, generated): per node its default
// containerField, its component and its fields, "name:Type:access" separated by spaces (access: f
// initializeOnly, e inputOutput, i inputOnly, o outputOnly). node_schema.hpp turns them into schemas.
#include <vector>

namespace cadnurbs {

struct StandardNodeRow {
  const char* type;
  const char* container_field;
  const char* component;
  const char* fields;
};

// Sorted by type.
const std::vector<StandardNodeRow>& x3d_standard_nodes();

}  // namespace cadnurbs
