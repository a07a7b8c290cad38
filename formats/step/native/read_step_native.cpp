#include "formats/step/native/read_step_native.hpp"

#include <algorithm>
#include <filesystem>

#include "core/geometry_error.hpp"
#include "core/length_unit.hpp"
#include "core/repair_trimming_loops.hpp"
#include "formats/step/native/native_face.hpp"
#include "formats/step/native/step_colours.hpp"
#include "formats/step/native/step_topology.hpp"
#include "formats/step/native/step_units.hpp"
#include "formats/common/file_io.hpp"
#include "formats/step/part21/parse_part21.hpp"

namespace cadnurbs {

namespace {

using namespace step;

// The surface type as OpenCASCADE names it (formats/brep/surface_type_name), for reports.
std::string surface_type(const StepSurface& surface) {
  if (std::holds_alternative<NurbsSurface>(surface)) return "BSplineSurface";
  static const char* const names[] = {"Plane",           "CylindricalSurface", "ConicalSurface",
                                      "SphericalSurface", "ToroidalSurface",   "SurfaceOfRevolution",
                                      "SurfaceOfLinearExtrusion"};
  return names[std::get<AnalyticSurface>(surface).index()];
}

// A solid or shell of the representation, with its faces' shells.
struct Container {
  EntityId entity;
  bool solid;
  std::vector<EntityId> shells;
};

struct Representation {
  EntityId entity = part21::none;
  std::vector<Container> containers;
};

// The B-rep items of a representation.
std::vector<Container> containers_of(const StepContext& context, EntityId representation) {
  const part21::Model& m = context.model;
  const auto& t = context.types;
  std::vector<Container> out;
  const part21::Value items = m.parameter(m.records(representation)[0], 1);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const EntityId item = items.item(k).reference();
    if (context.is(item, t.manifold_solid_brep)) {
      out.push_back({item, true, {m.parameter(m.records(item)[0], 1).reference()}});
    } else if (context.is(item, t.brep_with_voids)) {
      const auto& r = *m.record(item, t.brep_with_voids);
      if (m.parameter(r, 2).size() > 0) context.refuse(item, "a solid with voids is not read natively");
      out.push_back({item, true, {m.parameter(r, 1).reference()}});
    } else if (context.is(item, t.shell_based_surface_model)) {
      const part21::Value shells = m.parameter(m.records(item)[0], 1);
      for (std::size_t s = 0; s < shells.size(); ++s) out.push_back({shells.item(s).reference(), false, {shells.item(s).reference()}});
    } else if (context.is(item, t.mapped_item)) {
      context.refuse(item, "mapped items (placed copies) are not read natively");
    }
  }
  return out;
}

// The name of the product whose shape is `representation` (directly, or through a
// SHAPE_REPRESENTATION_RELATIONSHIP); empty when none.
std::string product_name(const StepContext& context, EntityId representation) {
  const part21::Model& m = context.model;
  const auto& t = context.types;
  std::vector<EntityId> shapes{representation};
  if (t.shape_representation_relationship != part21::none)
    for (EntityId relation : m.of_type(t.shape_representation_relationship)) {
      const auto& r = m.records(relation)[0];
      const EntityId a = m.parameter(r, 2).reference(), b = m.parameter(r, 3).reference();
      if (a == representation) shapes.push_back(b);
      if (b == representation) shapes.push_back(a);
    }
  if (t.shape_definition_representation == part21::none) return {};
  for (EntityId sdr : m.of_type(t.shape_definition_representation)) {
    const auto& r = m.records(sdr)[0];
    if (std::find(shapes.begin(), shapes.end(), m.parameter(r, 1).reference()) == shapes.end()) continue;
    const EntityId definition_shape = m.parameter(r, 0).reference();
    if (!context.is(definition_shape, t.product_definition_shape)) continue;
    const EntityId definition = m.parameter(m.records(definition_shape)[0], 2).reference();
    if (!context.is(definition, t.product_definition)) continue;
    const EntityId formation = m.parameter(m.records(definition)[0], 2).reference();
    const EntityId product = m.parameter(m.records(formation)[0], 2).reference();
    if (!context.is(product, t.product)) continue;
    return std::string(m.parameter(m.records(product)[0], 1).text());
  }
  return {};
}

Representation the_representation(const StepContext& context) {
  const auto& t = context.types;
  Representation found;
  for (TypeId type : {t.advanced_brep_shape_representation, t.manifold_surface_shape_representation, t.shape_representation}) {
    if (type == part21::none) continue;
    for (EntityId representation : context.model.of_type(type)) {
      auto containers = reading(context, representation, [&] { return containers_of(context, representation); });
      if (containers.empty()) continue;
      if (found.entity != part21::none)
        context.refuse(representation, "a second shape representation with solids (several parts) is not read natively");
      found = {representation, std::move(containers)};
    }
  }
  return found;
}

}  // namespace

BrepTranslation read_step_native(const std::string& path) {
  const part21::Model model = part21::read_part21_file(path);
  const StepTypes types(model);
  StepContext context{model, types};
  for (TypeId assembly : {types.next_assembly_usage_occurrence}) {
    if (assembly != part21::none && !model.of_type(assembly).empty())
      context.refuse(model.of_type(assembly)[0], "assemblies are not read natively yet");
  }
  const Representation representation = the_representation(context);
  if (representation.entity == part21::none) throw OutsideNativeSubset("no shape representation with a B-rep solid or shell");
  const StepUnits units = reading(context, representation.entity, [&] {
    return read_units(context, model.parameter(model.records(representation.entity)[0], 2).reference());
  });
  context.millimetres = units.millimetres;
  context.radians = units.radians;

  const std::string stem = std::filesystem::path(path).stem().string();
  BrepTranslation out;
  Scene& scene = out.scene;
  scene.root.name = reading(context, representation.entity, [&] { return product_name(context, representation.entity); });
  if (scene.root.name.empty()) scene.root.name = stem;
  scene.source_unit = length_unit_named(units.length_name).value_or(LengthUnit{units.length_name, units.millimetres});

  const auto colours = read_colours(context);
  auto colour_of = [&](EntityId entity) -> std::optional<Colour> {
    const auto found = colours.find(entity);
    return found == colours.end() ? std::nullopt : std::optional<Colour>(found->second);
  };
  TopologyReader topology(context);
  auto add_faces = [&](SceneNode& node, const std::string& node_path, const Container& container) {
    std::vector<EntityId> faces;
    for (EntityId shell : container.shells) {
      const auto more = topology.shell_faces(shell);
      faces.insert(faces.end(), more.begin(), more.end());
    }
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const StepFace face = topology.face(faces[i]);
      Shape shape;
      shape.source_entity = "face " + std::to_string(i + 1);
      shape.source_type = surface_type(face.surface);
      shape.colour = colour_of(faces[i]);
      try {
        double size = 0;
        Eigen::AlignedBox3d box;
        for (const auto& bound : face.bounds)
          for (const auto& use : bound.uses) box.extend(topology.edges()[static_cast<std::size_t>(use.edge)].start);
        size = box.isEmpty() ? 1.0 : std::max(box.diagonal().norm(), 1e-6);
        TrimmedSurface trimmed = native_face(face, topology.edges(), 1e-7 * size);
        for (auto& line : repair_trimming_loops(trimmed, "face"))
          out.repairs.push_back(node_path + " " + shape.source_entity + " (" + shape.source_type + "): " + line);
        shape.geometry = std::move(trimmed);
      } catch (const GeometryError& error) {
        context.refuse(faces[i], error.reason());
      }
      node.shapes.push_back(std::move(shape));
      ++out.face_count;
    }
  };
  if (representation.containers.size() == 1) {
    const Container& only = representation.containers[0];
    scene.root.colour = colour_of(only.entity);
    if (!scene.root.colour && only.solid) scene.root.colour = colour_of(only.shells[0]);
    add_faces(scene.root, scene.root.name, only);
  } else {
    int solids = 0, shells = 0;
    for (const Container& container : representation.containers) {
      SceneNode child;
      child.source_entity = container.solid ? "solid " + std::to_string(++solids) : "shell " + std::to_string(++shells);
      child.colour = colour_of(container.entity);
      add_faces(child, scene.root.name + "/" + child.source_entity, container);
      scene.root.children.push_back(std::move(child));
    }
  }
  if (out.face_count == 0) throw FileError(path + ": no faces in the file");
  out.degenerated_edges.assign(topology.edges().size(), false);
  return out;
}

}  // namespace cadnurbs
