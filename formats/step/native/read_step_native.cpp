#include "formats/step/native/read_step_native.hpp"

#include <algorithm>
#include <filesystem>
#include <unordered_set>

#include "core/geometry_error.hpp"
#include "core/length_unit.hpp"
#include "core/number_format.hpp"
#include "core/repair_trimming_loops.hpp"
#include "formats/step/native/native_face.hpp"
#include "formats/step/native/step_assembly.hpp"
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

// A solid or shell of a representation, with its faces' shells: a solid's outer shell, then its voids.
struct Container {
  EntityId entity;
  bool solid;
  std::vector<EntityId> shells;
  std::vector<bool> reversed;  // per shell: an ORIENTED_CLOSED_SHELL with orientation .F. (a void)
};

// The B-rep items of a representation (placements and other items left out).
std::vector<Container> containers_of(const StepContext& context, EntityId representation) {
  const part21::Model& m = context.model;
  const auto& t = context.types;
  std::vector<Container> out;
  const part21::Value items = m.parameter(m.records(representation)[0], 1);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const EntityId item = items.item(k).reference();
    if (context.is(item, t.manifold_solid_brep) && !context.is(item, t.brep_with_voids)) {
      out.push_back({item, true, {m.parameter(m.records(item)[0], 1).reference()}, {false}});
    } else if (context.is(item, t.brep_with_voids)) {
      // BREP_WITH_VOIDS(name, outer, voids): the outer shell's faces, then each void's, as OpenCASCADE
      // lists a solid's faces; a void is an ORIENTED_CLOSED_SHELL, .F. turning its faces' sense around.
      const auto& r = *m.record(item, t.brep_with_voids);
      const std::size_t first = r.count == 3 ? 1 : 0;  // simple: (name, outer, voids); complex: (voids)
      Container solid{item, true, {}, {}};
      const auto* outer_record = m.record(item, t.manifold_solid_brep);
      if (first == 0 && !outer_record) context.refuse(item, "a solid with voids without its outer shell");
      solid.shells.push_back((first == 1 ? m.parameter(r, 1) : m.parameter(*outer_record, 0)).reference());
      solid.reversed.push_back(false);
      const part21::Value voids = m.parameter(r, first + 1);
      for (std::size_t v = 0; v < voids.size(); ++v) {
        const EntityId shell = voids.item(v).reference();
        if (!context.is(shell, t.oriented_closed_shell)) {
          solid.shells.push_back(shell);
          solid.reversed.push_back(false);
          continue;
        }
        const auto& o = *m.record(shell, t.oriented_closed_shell);
        solid.shells.push_back(m.parameter(o, 2).reference());
        solid.reversed.push_back(!m.parameter(o, 3).boolean());
      }
      out.push_back(std::move(solid));
    } else if (context.is(item, t.shell_based_surface_model)) {
      const part21::Value shells = m.parameter(m.records(item)[0], 1);
      for (std::size_t s = 0; s < shells.size(); ++s)
        out.push_back({shells.item(s).reference(), false, {shells.item(s).reference()}, {false}});
    } else if (context.is(item, t.mapped_item)) {
      context.refuse(item, "mapped items (placed copies) are not read natively");
    }
  }
  return out;
}

// The representation with B-rep items, for a file whose products do not lead to one (no
// PRODUCT_DEFINITION, or a shape not tied to it); none when there is none. Refuses a second one.
EntityId any_representation(const StepContext& context) {
  const auto& t = context.types;
  EntityId found = part21::none;
  for (TypeId type : {t.advanced_brep_shape_representation, t.manifold_surface_shape_representation, t.shape_representation}) {
    if (type == part21::none) continue;
    for (EntityId representation : context.model.of_type(type)) {
      const bool has = reading(context, representation, [&] { return !containers_of(context, representation).empty(); });
      if (!has) continue;
      if (found != part21::none)
        context.refuse(representation, "a second shape representation with solids (several parts) is not read natively");
      found = representation;
    }
  }
  return found;
}

// A leaf product's content, converted once and copied for each of its placements.
struct PartContent {
  SceneNode node;  // colour, shapes, children "solid K" / "shell K"; no name, no transform
  // Repairs of its faces' trimming loops: the child's path ("" or "/solid K") and the line after PATH.
  std::vector<std::pair<std::string, std::string>> repairs;
  int faces = 0;
  bool empty = true;  // no B-rep items
};

class SceneBuilder {
 public:
  SceneBuilder(StepContext& context, BrepTranslation& out)
      : context_(context), out_(out), colours_(read_colours(context)), topology_(context) {}

  // The part made of `representations`' B-rep items (each read in its own context's units).
  const PartContent& part(std::size_t key, const std::vector<EntityId>& representations) {
    const auto found = parts_.find(key);
    if (found != parts_.end()) return found->second;
    PartContent content;
    std::vector<std::pair<Container, StepUnits>> containers;
    EntityId holding = part21::none;  // the representation with items besides placements
    for (EntityId representation : representations) {
      if (!reading(context_, representation, [&] { return holds_more_than_placements(representation); })) continue;
      // OpenCASCADE (STEPCAFControl_Reader) makes a part whose shape is in several representations an
      // assembly of them, each component named after its XCAF label ("=>[0:1:1:3]"): not matched here.
      if (holding != part21::none)
        context_.refuse(representation, "a part's shape in several representations (OpenCASCADE makes each a component named after its XCAF label)");
      holding = representation;
      const StepUnits units = reading(context_, representation, [&] {
        return read_units(context_, context_.model.parameter(context_.model.records(representation)[0], 2).reference());
      });
      for (auto& container : reading(context_, representation, [&] { return containers_of(context_, representation); }))
        containers.emplace_back(std::move(container), units);
      if (containers.empty())
        context_.refuse(representation, "a shape representation without B-rep solids or shells (curves, points)");
    }
    content.empty = containers.empty();
    if (containers.size() == 1) {
      const Container& only = containers[0].first;
      content.node.colour = colour_of(only.entity);
      if (!content.node.colour && only.solid) content.node.colour = colour_of(only.shells[0]);
      add_faces(content, content.node, "", only, containers[0].second);
    } else {
      int solids = 0, shells = 0;
      for (const auto& [container, units] : containers) {
        SceneNode child;
        child.source_entity = container.solid ? "solid " + std::to_string(++solids) : "shell " + std::to_string(++shells);
        child.colour = colour_of(container.entity);
        add_faces(content, child, "/" + child.source_entity, container, units);
        content.node.children.push_back(std::move(child));
      }
    }
    return parts_.emplace(key, std::move(content)).first->second;
  }

  // A copy of `content` placed as a node named `name` at `path`.
  SceneNode place(const PartContent& content, const std::string& path) {
    for (const auto& [child, line] : content.repairs) out_.repairs.push_back(path + child + " " + line);
    out_.face_count += content.faces;
    return content.node;
  }

  std::optional<Colour> colour_of(EntityId entity) const {
    const auto found = colours_.find(entity);
    return found == colours_.end() ? std::nullopt : std::optional<Colour>(found->second);
  }

  const TopologyReader& topology() const { return topology_; }

 private:
  // True when the representation holds items other than placements and presentation (callouts, text,
  // annotations: no shape in OpenCASCADE either). Refuses one holding other items besides its B-rep
  // (curve sets, points, ...): OpenCASCADE makes such a part an assembly of its items, each named after its
  // XCAF label.
  bool holds_more_than_placements(EntityId representation) const {
    const part21::Model& m = context_.model;
    const auto& t = context_.types;
    const part21::Value items = m.parameter(m.records(representation)[0], 1);
    bool more = false;
    for (std::size_t k = 0; k < items.size(); ++k) {
      const EntityId item = items.item(k).reference();
      if (context_.is(item, t.axis2_placement_3d) || presentation(item)) continue;
      more = true;
      if (!context_.is(item, t.manifold_solid_brep) && !context_.is(item, t.brep_with_voids) &&
          !context_.is(item, t.shell_based_surface_model) && !context_.is(item, t.mapped_item))
        context_.refuse(item, "an item besides the B-rep in a part's shape (OpenCASCADE makes the part an assembly of its items)");
    }
    return more;
  }

  bool presentation(EntityId item) const {
    for (const part21::Record& r : context_.model.records(item)) {
      const std::string_view name = context_.model.type_name(r.type);
      for (std::string_view word : {"CALLOUT", "TEXT", "ANNOTATION", "DRAUGHTING"})
        if (name.find(word) != std::string_view::npos) return true;
    }
    return false;
  }

  void add_faces(PartContent& content, SceneNode& node, const std::string& child_path, const Container& container,
                 const StepUnits& units) {
    context_.millimetres = units.millimetres;
    context_.radians = units.radians;
    for (std::size_t s = 0; s < container.shells.size(); ++s) {
      for (EntityId entity : topology_.shell_faces(container.shells[s])) {
        StepFace face = topology_.face(entity);
        if (container.reversed[s]) face.same_sense = !face.same_sense;
        Shape shape;
        shape.source_entity = "face " + std::to_string(node.shapes.size() + 1);
        shape.source_type = surface_type(face.surface);
        shape.colour = colour_of(entity);
        try {
          const double size = std::max(face_size(face, topology_.edges()), 1e-6);
          TrimmedSurface trimmed = native_face(face, topology_.edges(), 1e-7 * size);
          const std::string said = shape.source_entity + " (" + shape.source_type + "): ";
          for (const StepBound& bound : face.bounds)
            for (const EdgeUse& use : bound.uses) {
              const StepEdge& edge = topology_.edges()[use.edge];
              if (edge.vertex_moved > 0 && moves_said_.insert(use.edge).second)
                content.repairs.emplace_back(child_path, said + context_.model.entity_text(edge.entity) + ": a vertex " +
                                                             message_number(edge.vertex_moved) +
                                                             " mm off the curve: its end moved onto it");
            }
          for (auto& line : repair_trimming_loops(trimmed, "face")) content.repairs.emplace_back(child_path, said + line);
          shape.geometry = std::move(trimmed);
        } catch (const GeometryError& error) {
          context_.refuse(entity, error.reason());
        }
        node.shapes.push_back(std::move(shape));
        ++content.faces;
      }
    }
  }

  StepContext& context_;
  BrepTranslation& out_;
  std::unordered_map<EntityId, Colour> colours_;
  TopologyReader topology_;
  std::unordered_map<std::size_t, PartContent> parts_;
  std::unordered_set<int> moves_said_;  // edges whose moved vertex was said
};

// The scene node of product `p` (an assembly's components below it, a part's content in it).
SceneNode product_node(SceneBuilder& builder, const StepProductTree& tree, std::size_t p,
                       const std::string& name, const std::string& parent_path) {
  const StepProduct& product = tree.products[p];
  const std::string path = parent_path.empty() ? name : parent_path + "/" + name;
  SceneNode node;
  if (product.components.empty()) {
    const PartContent& content = builder.part(p, product.representations);
    // A part without a shape stays an empty node, as in OpenCASCADE's tree.
    node = builder.place(content, path);
  } else {
    for (const StepOccurrence& component : product.components) {
      // OpenCASCADE (xcaf_to_scene): the component's name, else its product's.
      const std::string child_name = component.name.empty() ? tree.products[component.product].name : component.name;
      SceneNode child = product_node(builder, tree, component.product, child_name, path);
      child.transform = component.placement;
      node.children.push_back(std::move(child));
    }
  }
  node.name = name;
  return node;
}

}  // namespace

BrepTranslation read_step_native(const std::string& path) {
  return read_step_native(read_file(path), path);
}

BrepTranslation read_step_native(std::string_view bytes, const std::string& path) {
  const part21::Model model = part21::parse_part21(bytes, path);
  const StepTypes types(model);
  StepContext context{model, types};
  StepProductTree tree = read_product_tree(context);
  const std::string stem = std::filesystem::path(path).stem().string();

  BrepTranslation out;
  Scene& scene = out.scene;
  SceneBuilder builder(context, out);
  // The products worth a node: assemblies, and parts with a B-rep shape (OpenCASCADE's free shapes).
  std::vector<std::size_t> roots;
  for (std::size_t p : tree.roots)
    if (!tree.products[p].components.empty() || !builder.part(p, tree.products[p].representations).empty) roots.push_back(p);
  // The units the file is said to be in: those of its first root's shape.
  EntityId unit_representation = part21::none;
  if (roots.empty()) {
    // No product leads to a shape: the one representation with B-rep items, named after the file.
    const EntityId representation = any_representation(context);
    if (representation == part21::none) throw OutsideNativeSubset("no shape representation with a B-rep solid or shell");
    tree.products.push_back({part21::none, "", {representation}, {}});
    roots.push_back(tree.products.size() - 1);
  }
  if (!tree.products[roots[0]].representations.empty()) unit_representation = tree.products[roots[0]].representations[0];
  const StepUnits units = unit_representation == part21::none ? StepUnits{} : reading(context, unit_representation, [&] {
    return read_units(context, model.parameter(model.records(unit_representation)[0], 2).reference());
  });
  scene.source_unit = length_unit_named(units.length_name).value_or(LengthUnit{units.length_name, units.millimetres});

  if (roots.size() == 1) {
    // xcaf_to_scene: one free shape is the root, named after its product, else the file.
    const std::string& name = tree.products[roots[0]].name;
    scene.root = product_node(builder, tree, roots[0], name.empty() ? stem : name, "");
  } else {
    scene.root.name = stem;
    for (std::size_t p : roots) scene.root.children.push_back(product_node(builder, tree, p, tree.products[p].name, stem));
  }
  if (out.face_count == 0) throw FileError(path + ": no faces in the file");
  out.degenerated_edges.assign(builder.topology().edges().size(), false);
  return out;
}

}  // namespace cadnurbs
