#include "formats/step/native/step_assembly.hpp"

#include <algorithm>
#include <unordered_map>

#include "formats/step/native/step_geometry.hpp"
#include "formats/step/native/step_units.hpp"

namespace cadnurbs::step {

namespace {

// What STEPCAFControl_Reader calls a string's useful length: without its trailing blanks.
bool useful(const part21::Value& value) {
  if (value.kind() != part21::ValueKind::string) return false;
  const std::string_view text = value.text();
  return text.find_last_not_of(" \t") != std::string_view::npos;
}

Eigen::Affine3d frame_matrix(const AxisFrame& frame) {
  Eigen::Affine3d out = Eigen::Affine3d::Identity();
  out.linear().col(0) = frame.x;
  out.linear().col(1) = frame.y;
  out.linear().col(2) = frame.z;
  out.translation() = frame.origin;
  return out;
}

class TreeReader {
 public:
  explicit TreeReader(StepContext& context) : c_(context), m_(context.model) {
    auto type = [&](const char* name) { return m_.type_named(name); };
    sdr_ = type("SHAPE_DEFINITION_REPRESENTATION");
    pds_ = type("PRODUCT_DEFINITION_SHAPE");
    pd_ = type("PRODUCT_DEFINITION");
    product_ = type("PRODUCT");
    nauo_ = type("NEXT_ASSEMBLY_USAGE_OCCURRENCE");
    cdsr_ = type("CONTEXT_DEPENDENT_SHAPE_REPRESENTATION");
    rr_ = type("REPRESENTATION_RELATIONSHIP");
    rrwt_ = type("REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION");
    idt_ = type("ITEM_DEFINED_TRANSFORMATION");
    srr_ = type("SHAPE_REPRESENTATION_RELATIONSHIP");
  }

  StepProductTree read() {
    StepProductTree tree;
    std::unordered_map<EntityId, std::size_t> index;  // PRODUCT_DEFINITION -> product
    for (EntityId definition : of(pd_)) {
      index.emplace(definition, tree.products.size());
      StepProduct product;
      product.definition = definition;
      product.name = reading(c_, definition, [&] { return product_name(definition); });
      tree.products.push_back(std::move(product));
    }
    if (tree.products.empty()) return tree;
    // Each product's shape representation, then those plainly related to it.
    for (EntityId sdr : of(sdr_)) {
      reading(c_, sdr, [&] {
        const auto& r = m_.records(sdr)[0];
        const EntityId definition_shape = m_.parameter(r, 0).reference();
        if (!c_.is(definition_shape, pds_)) return 0;
        const auto found = index.find(m_.parameter(m_.records(definition_shape)[0], 2).reference());
        if (found != index.end()) tree.products[found->second].representations.push_back(m_.parameter(r, 1).reference());
        return 0;
      });
    }
    std::unordered_map<EntityId, std::size_t> owner;  // representation -> product
    for (std::size_t p = 0; p < tree.products.size(); ++p)
      for (EntityId representation : tree.products[p].representations) owner.emplace(representation, p);
    for (std::size_t p = 0; p < tree.products.size(); ++p) {
      auto& reps = tree.products[p].representations;
      for (std::size_t k = 0; k < reps.size(); ++k)
        for (EntityId related : plainly_related(reps[k])) {
          if (std::find(reps.begin(), reps.end(), related) != reps.end()) continue;
          const auto other = owner.find(related);
          if (other != owner.end() && other->second != p)
            c_.refuse(related, "the shapes of two products related without a placement");
          reps.push_back(related);
          owner.emplace(related, p);
        }
    }

    // Occurrences: which product holds which, placed where.
    std::unordered_map<EntityId, EntityId> placement_of;  // NAUO -> its CDSR's representation relationship
    for (EntityId cdsr : of(cdsr_)) {
      reading(c_, cdsr, [&] {
        const auto& r = m_.records(cdsr)[0];
        const EntityId shape = m_.parameter(r, 1).reference();
        if (c_.is(shape, pds_)) placement_of[m_.parameter(m_.records(shape)[0], 2).reference()] = m_.parameter(r, 0).reference();
        return 0;
      });
    }
    std::vector<bool> used(tree.products.size(), false);
    for (EntityId usage : of(nauo_)) {
      reading(c_, usage, [&] {
        const auto& r = *m_.record(usage, nauo_);
        const auto parent = index.find(m_.parameter(r, 3).reference());
        const auto child = index.find(m_.parameter(r, 4).reference());
        if (parent == index.end() || child == index.end()) c_.refuse(usage, "an occurrence of something that is not a product definition");
        StepOccurrence occurrence;
        occurrence.usage = usage;
        occurrence.product = child->second;
        for (std::size_t k : {2u, 1u, 0u})
          if (useful(m_.parameter(r, k)) || k == 0) {
            occurrence.name = m_.parameter(r, k).kind() == part21::ValueKind::string ? std::string(m_.parameter(r, k).text()) : "";
            break;
          }
        const auto relation = placement_of.find(usage);
        if (relation == placement_of.end()) c_.refuse(usage, "an occurrence without a placement (no CONTEXT_DEPENDENT_SHAPE_REPRESENTATION)");
        occurrence.placement = placement(relation->second, tree.products[parent->second], tree.products[child->second]);
        tree.products[parent->second].components.push_back(std::move(occurrence));
        used[child->second] = true;
        return 0;
      });
    }
    for (std::size_t p = 0; p < tree.products.size(); ++p) {
      const StepProduct& product = tree.products[p];
      if (!product.components.empty() && !product.representations.empty() && has_geometry_items(product))
        c_.refuse(product.definition, "an assembly with shapes of its own besides its components is not read natively");
      if (!used[p]) tree.roots.push_back(p);
    }
    check_acyclic(tree);
    return tree;
  }

 private:
  std::span<const EntityId> of(TypeId type) const {
    if (type == part21::none) return {};
    return m_.of_type(type);
  }

  std::string product_name(EntityId definition) const {
    const EntityId formation = m_.parameter(m_.records(definition)[0], 2).reference();
    const EntityId product = m_.parameter(m_.records(formation)[0], 2).reference();
    if (!c_.is(product, product_)) return {};
    const auto& r = *m_.record(product, product_);
    if (useful(m_.parameter(r, 1))) return std::string(m_.parameter(r, 1).text());
    return m_.parameter(r, 0).kind() == part21::ValueKind::string ? std::string(m_.parameter(r, 0).text()) : "";
  }

  // Representations related to `representation` by a SHAPE_REPRESENTATION_RELATIONSHIP without a
  // transformation (the product's geometry kept in another representation), either way round.
  std::vector<EntityId> plainly_related(EntityId representation) const {
    std::vector<EntityId> out;
    for (EntityId relation : of(srr_)) {
      if (c_.is(relation, rrwt_)) continue;
      reading(c_, relation, [&] {
        const part21::Record& r = c_.is(relation, rr_) ? *m_.record(relation, rr_) : m_.records(relation)[0];
        if (r.count < 4) return 0;
        const EntityId a = m_.parameter(r, 2).reference(), b = m_.parameter(r, 3).reference();
        if (a == representation) out.push_back(b);
        if (b == representation) out.push_back(a);
        return 0;
      });
    }
    return out;
  }

  // True when one of the product's representations holds more than placements (solids, shells, ...).
  bool has_geometry_items(const StepProduct& product) const {
    const TypeId placement = c_.types.axis2_placement_3d;
    // An item that is not a reference (a broken file) is refused naming the representation; found by fuzz_long.
    for (EntityId representation : product.representations)
      if (reading(c_, representation, [&] {
            const part21::Value items = m_.parameter(m_.records(representation)[0], 1);
            for (std::size_t k = 0; k < items.size(); ++k)
              if (!c_.is(items.item(k).reference(), placement)) return true;
            return false;
          }))
        return true;
    return false;
  }

  // The frame of `item`, a placement in `representation`, in that representation's units (millimetres).
  Eigen::Affine3d frame_in(EntityId item, EntityId representation) {
    const StepUnits units = read_units(c_, m_.parameter(m_.records(representation)[0], 2).reference());
    const double saved = c_.millimetres;
    c_.millimetres = units.millimetres;
    const AxisFrame frame = read_frame(c_, item);
    c_.millimetres = saved;
    return frame_matrix(frame);
  }

  // The placement of `child` in `parent` from a REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION: its
  // ITEM_DEFINED_TRANSFORMATION relates a placement in the child's representation to one in the parent's,
  // and the child goes where its placement lands on the parent's. Writers differ on which of rep_1 and
  // rep_2 is the child (AP214's recommended practice: rep_1; SolidWorks: rep_2), so the representations say.
  Eigen::Affine3d placement(EntityId relation, const StepProduct& parent, const StepProduct& child) {
    if (!c_.is(relation, rr_) || !c_.is(relation, rrwt_))
      c_.refuse(relation, "a placement that is not a REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION");
    const auto& r = *m_.record(relation, rr_);
    const EntityId rep_1 = m_.parameter(r, 2).reference(), rep_2 = m_.parameter(r, 3).reference();
    const EntityId transformation = m_.parameter(*m_.record(relation, rrwt_), 0).reference();
    if (!c_.is(transformation, idt_))
      c_.refuse(transformation, "a placement that is not an ITEM_DEFINED_TRANSFORMATION");
    const auto& t = *m_.record(transformation, idt_);
    const EntityId item_1 = m_.parameter(t, 2).reference(), item_2 = m_.parameter(t, 3).reference();
    auto holds = [](const StepProduct& product, EntityId representation) {
      return std::find(product.representations.begin(), product.representations.end(), representation) !=
             product.representations.end();
    };
    if (holds(child, rep_1) && holds(parent, rep_2)) {
      return frame_in(item_2, rep_2) * frame_in(item_1, rep_1).inverse();
    }
    if (holds(child, rep_2) && holds(parent, rep_1)) {
      return frame_in(item_1, rep_1) * frame_in(item_2, rep_2).inverse();
    }
    c_.refuse(relation, "a placement relating representations other than its occurrence's products'");
  }

  void check_acyclic(const StepProductTree& tree) const {
    // 0 unvisited, 1 on the path, 2 done.
    std::vector<int> state(tree.products.size(), 0);
    auto visit = [&](auto&& self, std::size_t p) -> void {
      if (state[p] == 2) return;
      if (state[p] == 1) c_.refuse(tree.products[p].definition, "a product that contains itself");
      state[p] = 1;
      for (const auto& component : tree.products[p].components) self(self, component.product);
      state[p] = 2;
    };
    for (std::size_t p = 0; p < tree.products.size(); ++p) visit(visit, p);
  }

  StepContext& c_;
  const part21::Model& m_;
  TypeId sdr_, pds_, pd_, product_, nauo_, cdsr_, rr_, rrwt_, idt_, srr_;
};

}  // namespace

StepProductTree read_product_tree(StepContext& context) { return TreeReader(context).read(); }

}  // namespace cadnurbs::step
