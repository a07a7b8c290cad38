#pragma once
// The primitive values of a .cnb payload (docs/cnb.md, "Types"): bytes, LEB128 varints, zig-zag signed
// varints, little-endian float64 and length-prefixed strings. Every byte carries a context (what kind of
// field it belongs to) so that a context-modelling entropy coder can keep separate statistics per kind;
// a plain byte buffer ignores it.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace cadnurbs::cnb {

// What a byte is part of. A varint's first byte and its continuation bytes get different contexts.
// A traversal-coded mesh's connectivity symbols, and its vertices: differences from the prediction,
// ranks among the values met, and which axes are such values (cnb_vertex_values.hpp); in a mesh group,
// which of its meshes each triangle belongs to.
enum class Field : uint8_t {
  structure, count, text, knot, weight, point, trim, index, raw, symbol, mesh_point, mesh_rank, mesh_axes,
  mesh_member
};
// The format version writers write (docs/cnb.md); readers pass on the file's, since the contexts
// bytes take depend on it.
constexpr uint8_t format_version = 9;

constexpr int field_count = 14;
// Contexts: 2 per field (first / continuation byte of a varint), 8 for the bytes of a float64, then (format
// version 4 on) one per mesh symbol for the symbol after it, and the first byte of a vertex's rank and of
// its difference from the prediction on axes 1 and 2 (axis 0 keeps the field's own); then (version 8 on)
// one per vertex predictor for the predictor after it; then (version 9 on) one per shape of the border
// after the gate (cnb_gate_shape.hpp) for a traversal's symbol after a new vertex beyond a gate, one
// for the first byte of an earlier vertex's place along the border, and 7 for vertex values whose
// prediction is or is not listed (cnb_vertex_values.hpp).
constexpr int mesh_symbol_count = 7;
constexpr int vertex_predictor_contexts = 4;
constexpr int gate_symbol_contexts = 5;
constexpr int listed_prediction_contexts = 7;
constexpr int context_count = 2 * field_count + 8 + mesh_symbol_count + 4 + vertex_predictor_contexts +
                              gate_symbol_contexts + 1 + listed_prediction_contexts;

// Whether `context` is one of a float64's 8 (after the fields' own 2 each).
constexpr bool float64_context(int context) { return context >= 2 * field_count && context < 2 * field_count + 8; }
// The context of a field's byte, or of a varint's first byte (its continuation bytes take the next one).
int first_context(Field field);
// The context of a mesh symbol that follows `previous` (< mesh_symbol_count), version 4 on.
int symbol_context(uint8_t previous);
// The context of the first byte of a vertex coordinate's rank (Field::mesh_rank) or difference
// (Field::mesh_point) on `axis`, version 4 on; axis 0 is the field's first context.
int axis_context(Field field, int axis);
// The context of a new vertex's predictor that follows `previous` (< vertex_predictor_contexts), version 8
// on (cnb_vertex_predictors.hpp).
int predictor_context(uint8_t previous);
// The context of a traversal's symbol after a new vertex beyond a gate of shape `shape` (< 5), version 9
// on.
int gate_symbol_context(int shape);
// The context of the first byte of an earlier vertex's place along the border (Field::index continues
// it), version 9 on.
int border_place_context();
// Version 9 on: the context of the first byte of a vertex coordinate's rank or difference on `axis` by
// whether its prediction is a listed value (a rank's where it is, and a difference's where it is not, are
// axis_context's), and of the axes byte by whether all three predictions are (where they are, the field's).
int value_context(Field field, int axis, bool prediction_listed);
int axes_context(bool all_predictions_listed);

// A damaged or impossible payload: where (byte offset in the decoded payload) and why.
struct PayloadError : std::runtime_error {
  PayloadError(size_t offset, const std::string& reason)
      : std::runtime_error(reason), offset(offset) {}
  size_t offset;
};

// Builds the decoded payload, remembering each byte's context.
class ByteWriter {
 public:
  void byte(uint8_t value, Field field = Field::structure);
  // A byte of a field that is never a varint, in its first (second = false) or second context: two
  // models for one field, chosen by what came before (the reader makes the same choice).
  void byte(uint8_t value, Field field, bool second);
  void varuint(uint64_t value, Field field);
  void varsint(int64_t value, Field field);  // zig-zag: 0, -1, 1, -2, ... -> 0, 1, 2, 3, ...
  // A byte in the given context; a varsint whose first byte takes `first_context` and whose continuation
  // bytes take the field's.
  void byte_in(uint8_t value, int context);
  void varsint_in(int64_t value, Field field, int first_context);
  void varuint_in(uint64_t value, Field field, int first_context);
  void float64(double value);
  void float32(float value);  // in the contexts of a float64's upper four bytes
  void text(const std::string& value);
  void append(const ByteWriter& other);

  const std::string& bytes() const { return bytes_; }
  const std::vector<uint8_t>& contexts() const { return contexts_; }

 private:
  void put(uint8_t value, int context);
  void varuint_from(uint64_t value, Field field, int first_context);
  std::string bytes_;
  std::vector<uint8_t> contexts_;
};

// Where a reader takes its bytes from: a buffer, or an entropy decoder that needs the context.
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual uint8_t next(int context) = 0;
};

// Reads the payload back. Every read past `size` bytes, every count that cannot fit in the bytes left,
// and every over-long varint throws PayloadError with the offset of the offending value.
class ByteReader {
 public:
  ByteReader(ByteSource& source, size_t size) : source_(source), size_(size) {}

  uint8_t byte(Field field = Field::structure);
  uint8_t byte(Field field, bool second);
  uint64_t varuint(Field field);
  int64_t varsint(Field field);
  uint8_t byte_in(int context);  // as ByteWriter::byte_in and varsint_in
  int64_t varsint_in(Field field, int first_context);
  uint64_t varuint_in(Field field, int first_context);
  double float64();
  float float32();
  std::string text();
  // A count of things that each take at least `min_bytes` bytes: refused (before anything is allocated)
  // when the bytes left cannot hold that many.
  size_t count(size_t min_bytes = 1, Field field = Field::count);

  size_t offset() const { return offset_; }
  size_t left() const { return size_ - offset_; }
  [[noreturn]] void fail(const std::string& reason, size_t at) const { throw PayloadError(at, reason); }
  [[noreturn]] void fail(const std::string& reason) const { throw PayloadError(offset_, reason); }

 private:
  uint8_t take(int context);
  uint64_t varuint_from(Field field, int first_context);
  ByteSource& source_;
  size_t size_;
  size_t offset_ = 0;
};

// A source over bytes already in memory.
class BufferSource : public ByteSource {
 public:
  explicit BufferSource(const std::string& bytes) : bytes_(bytes) {}
  uint8_t next(int) override { return static_cast<uint8_t>(bytes_[position_++]); }

 private:
  const std::string& bytes_;
  size_t position_ = 0;
};

inline uint64_t zigzag(int64_t v) { return (static_cast<uint64_t>(v) << 1) ^ static_cast<uint64_t>(v >> 63); }
inline int64_t unzigzag(uint64_t u) { return static_cast<int64_t>(u >> 1) ^ -static_cast<int64_t>(u & 1); }

}  // namespace cadnurbs::cnb
