#include "formats/step/part21/part21_model.hpp"

#include <algorithm>

namespace cadnurbs::part21 {

std::string_view kind_name(ValueKind kind) {
  switch (kind) {
    case ValueKind::unset: return "$ (unset)";
    case ValueKind::derived: return "* (derived)";
    case ValueKind::integer: return "an integer";
    case ValueKind::real: return "a real";
    case ValueKind::string: return "a string";
    case ValueKind::enumeration: return "an enumeration";
    case ValueKind::binary: return "a binary";
    case ValueKind::reference: return "a reference";
    case ValueKind::list: return "a list";
    case ValueKind::typed: return "a typed parameter";
  }
  return "an unknown kind";
}

void Value::refuse(std::string_view expected) const {
  throw ValueError("expected " + std::string(expected) + ", found " + std::string(kind_name(slot_->kind)));
}

double Value::number() const {
  if (slot_->kind == ValueKind::real) return slot_->real;
  if (slot_->kind == ValueKind::integer) return static_cast<double>(slot_->integer);
  refuse("a number");
}

std::int64_t Value::integer() const {
  if (slot_->kind != ValueKind::integer) refuse("an integer");
  return slot_->integer;
}

bool Value::boolean() const {
  if (slot_->kind != ValueKind::enumeration) refuse("a boolean (.T. or .F.)");
  const std::string_view name = text();
  if (name == "T") return true;
  if (name == "F") return false;
  throw ValueError("expected a boolean (.T. or .F.), found ." + std::string(name) + ".");
}

std::string_view Value::text() const {
  const ValueKind kind = slot_->kind;
  if (kind != ValueKind::string && kind != ValueKind::enumeration && kind != ValueKind::binary)
    refuse("a string, enumeration or binary");
  return std::string_view(model_->text_).substr(slot_->index, slot_->aux);
}

EntityId Value::reference() const {
  if (slot_->kind != ValueKind::reference) refuse("a reference");
  return slot_->aux;
}

std::int64_t Value::reference_number() const {
  if (slot_->kind != ValueKind::reference) refuse("a reference");
  return slot_->integer;
}

std::size_t Value::size() const {
  if (slot_->kind != ValueKind::list) refuse("a list");
  return slot_->aux;
}

Value Value::item(std::size_t k) const {
  if (slot_->kind != ValueKind::list) refuse("a list");
  if (k >= slot_->aux)
    throw ValueError("a list of " + std::to_string(slot_->aux) + " items has no item " + std::to_string(k + 1));
  return Value(*model_, model_->slots_[slot_->index + k]);
}

TypeId Value::type() const {
  if (slot_->kind != ValueKind::typed) refuse("a typed parameter");
  return slot_->aux;
}

Value Value::inner() const {
  if (slot_->kind != ValueKind::typed) refuse("a typed parameter");
  return Value(*model_, model_->slots_[slot_->index]);
}

EntityId Model::find(std::int64_t number) const {
  if (!dense_ids_.empty() || sorted_ids_.empty()) {
    if (number < 1 || static_cast<std::uint64_t>(number) > dense_ids_.size()) return none;
    return dense_ids_[static_cast<std::size_t>(number - 1)];
  }
  const auto at = std::lower_bound(sorted_ids_.begin(), sorted_ids_.end(), number,
                                   [](const std::pair<std::int64_t, EntityId>& entry, std::int64_t n) { return entry.first < n; });
  return (at != sorted_ids_.end() && at->first == number) ? at->second : none;
}

const Record* Model::record(EntityId id, TypeId type) const {
  for (const Record& candidate : records(id))
    if (candidate.type == type) return &candidate;
  return nullptr;
}

TypeId Model::type(EntityId id) const {
  const Entity& entity = entities_[id];
  return entity.complex ? none : records_[entity.first_record].type;
}

bool Model::is(EntityId id, TypeId type) const { return record(id, type) != nullptr; }

Value Model::parameter(const Record& record, std::size_t k) const {
  if (k >= record.count)
    throw ValueError(std::string(type_name(record.type)) + " has " + std::to_string(record.count) + " parameter" +
                     (record.count == 1 ? "" : "s") + ", not " + std::to_string(k + 1));
  return Value(*this, slots_[record.first + k]);
}

TypeId Model::type_named(std::string_view upper_case_name) const {
  const auto found = type_ids_.find(upper_case_name);
  return found == type_ids_.end() ? none : found->second;
}

std::span<const EntityId> Model::of_type(TypeId type) const {
  if (type >= type_names_.size()) return {};
  return {type_entities_.data() + type_first_[type], type_first_[type + 1] - type_first_[type]};
}

std::string Model::entity_text(EntityId id) const {
  std::string text = "#" + std::to_string(number(id)) + " ";
  if (!entities_[id].complex) return text + std::string(type_name(type(id)));
  text += "(";
  bool first = true;
  for (const Record& part : records(id)) {
    if (!first) text += " ";
    text += type_name(part.type);
    first = false;
  }
  return text + ")";
}

}  // namespace cadnurbs::part21
