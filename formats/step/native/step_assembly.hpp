#pragma once
// A STEP file's products as a tree (ISO 10303-44 product structure as AP203/AP214/AP242 use it): each
// PRODUCT_DEFINITION with the shape representations holding its geometry (its SHAPE_DEFINITION_
// REPRESENTATION's, and those linked to it by plain SHAPE_REPRESENTATION_RELATIONSHIPs), and its components:
// NEXT_ASSEMBLY_USAGE_OCCURRENCEs placed by a CONTEXT_DEPENDENT_SHAPE_REPRESENTATION whose
// REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION carries an ITEM_DEFINED_TRANSFORMATION.
// Names follow OpenCASCADE's STEPCAFControl_Reader (so the native scene's tree matches its XCAF tree):
// a product by its PRODUCT name, else its id; an occurrence by its description, else its name, else its id.
// Refuses (OutsideNativeSubset naming the entity): an occurrence without a placement, a transformation
// that is not an ITEM_DEFINED_TRANSFORMATION of two AXIS2_PLACEMENT_3Ds, a relationship that relates
// neither of the occurrence's products' representations, a product that is its own component (a cycle),
// an assembly that has geometry of its own besides its components.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "formats/step/native/step_context.hpp"

namespace cadnurbs::step {

struct StepOccurrence {
  EntityId usage = part21::none;  // the NEXT_ASSEMBLY_USAGE_OCCURRENCE
  std::string name;               // description, else name, else id (may be empty)
  std::size_t product = 0;        // index in StepProductTree::products
  Eigen::Affine3d placement = Eigen::Affine3d::Identity();  // the component's millimetres -> the assembly's
};

struct StepProduct {
  EntityId definition = part21::none;  // the PRODUCT_DEFINITION
  std::string name;                    // the PRODUCT's name, else its id
  // Shape representations holding its geometry, the SHAPE_DEFINITION_REPRESENTATION's first.
  std::vector<EntityId> representations;
  std::vector<StepOccurrence> components;  // file order of the occurrences
};

struct StepProductTree {
  std::vector<StepProduct> products;  // file order of the PRODUCT_DEFINITIONs
  std::vector<std::size_t> roots;     // products no occurrence uses, in file order
};

// Takes the file. Returns its products; empty when it has no PRODUCT_DEFINITION with a shape.
// `context`'s units are changed while placements are read (each in its representation's units).
StepProductTree read_product_tree(StepContext& context);

}  // namespace cadnurbs::step
