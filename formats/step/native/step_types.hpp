#pragma once
// The entity types the native STEP reader understands, looked up once per file: one table of names, so
// the builder compares type ids, never strings. A type the file does not use gets part21::none.
#include "formats/step/part21/part21_model.hpp"

namespace cadnurbs::step {

using part21::EntityId;
using part21::TypeId;

struct StepTypes {
  // geometry
  TypeId cartesian_point, direction, vector, axis1_placement, axis2_placement_3d;
  TypeId line, circle, ellipse, b_spline_curve, b_spline_curve_with_knots, rational_b_spline_curve;
  TypeId uniform_curve, quasi_uniform_curve, bezier_curve;  // B-spline curves whose knots are implied
  TypeId surface_curve, seam_curve, trimmed_curve;
  TypeId plane, cylindrical_surface, conical_surface, spherical_surface, toroidal_surface;
  TypeId surface_of_revolution, surface_of_linear_extrusion;
  TypeId b_spline_surface, b_spline_surface_with_knots, rational_b_spline_surface, offset_surface;
  TypeId uniform_surface, quasi_uniform_surface, bezier_surface;
  // topology
  TypeId advanced_face, face_bound, face_outer_bound, edge_loop, vertex_loop, oriented_edge, edge_curve,
      vertex_point;
  TypeId closed_shell, open_shell, oriented_closed_shell, manifold_solid_brep, brep_with_voids,
      shell_based_surface_model;
  // representations and products
  TypeId advanced_brep_shape_representation, manifold_surface_shape_representation, shape_representation;
  TypeId shape_representation_relationship, shape_definition_representation, product_definition_shape;
  TypeId product_definition, product_definition_formation, product_definition_formation_with_specified_source,
      product;
  TypeId next_assembly_usage_occurrence, context_dependent_shape_representation, item_defined_transformation;
  TypeId mapped_item;
  // units
  TypeId length_unit, plane_angle_unit, si_unit, conversion_based_unit, global_unit_assigned_context;
  // presentation
  TypeId styled_item, over_riding_styled_item, presentation_style_assignment, surface_style_usage,
      surface_side_style, surface_style_fill_area, fill_area_style, fill_area_style_colour, colour_rgb,
      draughting_pre_defined_colour;

  explicit StepTypes(const part21::Model& model);
};

}  // namespace cadnurbs::step
