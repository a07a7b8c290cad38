#pragma once
// What every part of the native STEP reader reads through: the entity table, its type ids, the file's
// units, and the one error that hands a file to OpenCASCADE.
#include <stdexcept>
#include <string>

#include "formats/step/native/step_types.hpp"

namespace cadnurbs::step {

// Why the native reader cannot read a file: an entity outside its subset, or one it cannot convert.
// what() is "#N TYPE: reason", the entity that sent the file to OpenCASCADE.
class OutsideNativeSubset : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct StepContext {
  const part21::Model& model;
  const StepTypes& types;
  double millimetres = 1.0;  // one length unit of the file, in millimetres
  double radians = 1.0;      // one plane-angle unit of the file, in radians

  [[noreturn]] void refuse(EntityId entity, const std::string& reason) const {
    throw OutsideNativeSubset(model.entity_text(entity) + ": " + reason);
  }
  // The record of `type` in `entity` (a simple instance of it, or a complex one holding it); refuses
  // otherwise, saying what was expected.
  const part21::Record& record(EntityId entity, TypeId type, const char* expected) const {
    const part21::Record* found = type == part21::none ? nullptr : model.record(entity, type);
    if (!found) refuse(entity, std::string("expected ") + expected);
    return *found;
  }
  bool is(EntityId entity, TypeId type) const { return type != part21::none && model.is(entity, type); }
};

// Runs `read` for `entity`, turning a parameter of the wrong kind (part21::ValueError) into a refusal
// naming the entity.
template <class Read>
auto reading(const StepContext& context, EntityId entity, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const part21::ValueError& error) {
    context.refuse(entity, error.what());
  }
}

}  // namespace cadnurbs::step
