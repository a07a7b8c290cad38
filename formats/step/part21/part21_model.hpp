#pragma once
// The entity table of an ISO 10303-21 (STEP Part 21) file, as parse_part21 fills it, and Value, a cheap
// view of one parameter. In: nothing (parse_part21 builds it). Out: every DATA-section instance in file
// order (its #number, line, type records and parameters), references resolved to entity ids, the type
// names with the instances of each, the HEADER's FILE_SCHEMA names. Refuses, through ValueError, reading
// a parameter as a kind it is not (a builder asking a list for a real names its mistake instead of
// reading garbage). Storage is flat: every parameter is one 16-byte slot, a list's items contiguous, the
// text of strings, enumerations and binaries in one arena; nothing is allocated per entity.
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace cadnurbs::part21 {

using EntityId = std::uint32_t;  // index in the model's entity table (NOT the file's #number)
using TypeId = std::uint32_t;    // index in the model's table of type names
inline constexpr std::uint32_t none = 0xFFFFFFFFu;

enum class ValueKind : std::uint8_t { unset /* $ */, derived /* * */, integer, real, string, enumeration, binary, reference, list, typed };

// A parameter read as a kind it is not; what() e.g. "expected a real, found a list".
class ValueError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "a real", "a list", ... for messages.
std::string_view kind_name(ValueKind kind);

namespace detail {
// One parameter. aux: a list's item count, a typed parameter's TypeId, a reference's resolved EntityId,
// a text's length. payload: the integer, the real, a list's first item slot, a typed parameter's inner
// slot, a reference's #number, a text's offset in the arena.
struct Slot {
  ValueKind kind;
  std::uint32_t aux;
  union {
    std::int64_t integer;
    double real;
    std::uint64_t index;
  };
};
static_assert(sizeof(Slot) == 16);
}  // namespace detail

class Model;

// A cheap view (copyable) of one parameter, valid while its Model lives.
class Value {
 public:
  Value(const Model& model, const detail::Slot& slot) : model_(&model), slot_(&slot) {}
  ValueKind kind() const { return slot_->kind; }
  // Each accessor throws ValueError when the kind does not fit.
  double number() const;            // real or integer
  std::int64_t integer() const;
  bool boolean() const;             // enumeration .T. / .F. (anything else throws)
  std::string_view text() const;    // string: decoded UTF-8; enumeration: its name without the dots; binary: its hex digits
  EntityId reference() const;       // the referenced entity, resolved
  std::int64_t reference_number() const;  // the referenced entity's #number as written
  std::size_t size() const;         // list: number of items
  Value item(std::size_t k) const;  // list item k (throws ValueError past the end)
  TypeId type() const;              // typed parameter such as LENGTH_MEASURE(2.): its type
  Value inner() const;              // typed parameter: its value

 private:
  [[noreturn]] void refuse(std::string_view expected) const;
  const Model* model_;
  const detail::Slot* slot_;
};

struct Record {  // one (partial) entity type's parameters
  TypeId type;
  std::uint32_t first, count;  // slots first .. first + count - 1
};

class Model {
 public:
  std::size_t size() const { return entities_.size(); }  // entities in DATA sections
  EntityId find(std::int64_t number) const;               // #number -> id; none when absent
  std::int64_t number(EntityId id) const { return entities_[id].number; }
  long line(EntityId id) const { return static_cast<long>(entities_[id].line); }  // 1-based line where the instance starts
  // 1 for a simple instance; a complex instance's partial records as written.
  std::span<const Record> records(EntityId id) const {
    return {records_.data() + entities_[id].first_record, entities_[id].record_count};
  }
  const Record* record(EntityId id, TypeId type) const;  // that type's (partial) record, or nullptr
  TypeId type(EntityId id) const;                          // a simple instance's type; none for complex ones
  bool is_complex(EntityId id) const { return entities_[id].complex; }
  bool is(EntityId id, TypeId type) const;  // simple of that type, or complex with such a record
  // Throws ValueError when k >= count ("CARTESIAN_POINT has 2 parameters, not 3").
  Value parameter(const Record& record, std::size_t k) const;
  std::string_view type_name(TypeId type) const { return type_names_[type]; }  // upper case as in the file
  // none when no instance and no typed parameter uses that type (of_type tells which have instances).
  TypeId type_named(std::string_view upper_case_name) const;
  std::size_t type_count() const { return type_names_.size(); }
  std::span<const EntityId> of_type(TypeId type) const;  // simple instances of the type and complex ones holding it, file order
  // For messages: "#12 ADVANCED_FACE"; a complex instance "#12 (BOUNDED_SURFACE B_SPLINE_SURFACE ...)".
  std::string entity_text(EntityId id) const;
  std::span<const std::string> file_schemas() const { return file_schemas_; }  // FILE_SCHEMA's names from the HEADER
  std::size_t reference_count() const { return reference_count_; }  // #N parameters in DATA sections

 private:
  friend class Value;
  friend class Part21Parser;

  struct Entity {
    std::int64_t number;
    std::uint32_t line;
    std::uint32_t first_record;
    std::uint32_t record_count : 31;
    std::uint32_t complex : 1;
  };
  struct NameHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view name) const { return std::hash<std::string_view>{}(name); }
  };

  std::vector<Entity> entities_;
  std::vector<Record> records_;
  std::vector<detail::Slot> slots_;
  std::string text_;  // the decoded text of every string, enumeration and binary
  std::vector<std::string> type_names_;
  std::unordered_map<std::string, TypeId, NameHash, std::equal_to<>> type_ids_;
  std::vector<std::uint32_t> type_first_;  // of_type(t) = type_entities_[type_first_[t] .. type_first_[t + 1])
  std::vector<EntityId> type_entities_;
  // #number -> id: dense when the numbers are compact (index number - 1), else sorted pairs.
  std::vector<EntityId> dense_ids_;
  std::vector<std::pair<std::int64_t, EntityId>> sorted_ids_;
  std::vector<std::string> file_schemas_;
  std::size_t reference_count_ = 0;
};

}  // namespace cadnurbs::part21
