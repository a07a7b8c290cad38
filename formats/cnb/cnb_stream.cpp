#include "formats/cnb/cnb_stream.hpp"

#include <bit>
#include <cstring>

#include "core/bit_cast.hpp"

namespace cadnurbs::cnb {

int first_context(Field f) { return 2 * static_cast<int>(f); }

namespace {
int continuation_context(Field f) { return 2 * static_cast<int>(f) + 1; }
int float_context(int byte_index) { return 2 * field_count + byte_index; }
constexpr int first_symbol_context = 2 * field_count + 8;
constexpr int first_axis_context = first_symbol_context + mesh_symbol_count;
constexpr int first_predictor_context = first_axis_context + 4;
constexpr int first_gate_symbol_context = first_predictor_context + vertex_predictor_contexts;
constexpr int border_place_context_number = first_gate_symbol_context + gate_symbol_contexts;
constexpr int first_value_context = border_place_context_number + 1;
static_assert(first_value_context + listed_prediction_contexts == context_count, "every context has its place");
static_assert(context_count <= 256, "a context is a byte");
}  // namespace

int symbol_context(uint8_t previous) { return first_symbol_context + previous; }

int predictor_context(uint8_t previous) { return first_predictor_context + previous; }

int gate_symbol_context(int shape) { return first_gate_symbol_context + shape; }

int border_place_context() { return border_place_context_number; }

int value_context(Field field, int axis, bool prediction_listed) {
  if (field == Field::mesh_rank) return prediction_listed ? axis_context(field, axis) : first_value_context + axis;
  return prediction_listed ? first_value_context + 3 + axis : axis_context(field, axis);
}

int axes_context(bool all_predictions_listed) {
  return all_predictions_listed ? first_context(Field::mesh_axes) : first_value_context + 6;
}

int axis_context(Field field, int axis) {
  if (axis == 0) return first_context(field);
  return first_axis_context + (field == Field::mesh_rank ? 0 : 2) + axis - 1;
}

void ByteWriter::put(uint8_t value, int context) {
  bytes_.push_back(static_cast<char>(value));
  contexts_.push_back(static_cast<uint8_t>(context));
}

void ByteWriter::byte(uint8_t value, Field field) { put(value, first_context(field)); }
void ByteWriter::byte(uint8_t value, Field field, bool second) {
  put(value, second ? continuation_context(field) : first_context(field));
}

void ByteWriter::byte_in(uint8_t value, int context) { put(value, context); }

void ByteWriter::varsint_in(int64_t value, Field field, int first) { varuint_from(zigzag(value), field, first); }
void ByteWriter::varuint_in(uint64_t value, Field field, int first) { varuint_from(value, field, first); }

void ByteWriter::varuint(uint64_t value, Field field) { varuint_from(value, field, first_context(field)); }

void ByteWriter::varuint_from(uint64_t value, Field field, int first) {
  int context = first;
  while (value >= 0x80) {
    put(static_cast<uint8_t>(value | 0x80), context);
    value >>= 7;
    context = continuation_context(field);
  }
  put(static_cast<uint8_t>(value), context);
}

void ByteWriter::varsint(int64_t value, Field field) { varuint(zigzag(value), field); }

void ByteWriter::float64(double value) {
  const uint64_t bits = bit_cast<uint64_t>(value);
  for (int i = 0; i < 8; ++i) put(static_cast<uint8_t>(bits >> (8 * i)), float_context(i));
}

void ByteWriter::float32(float value) {
  const uint32_t bits = bit_cast<uint32_t>(value);
  for (int i = 0; i < 4; ++i) put(static_cast<uint8_t>(bits >> (8 * i)), float_context(4 + i));
}

void ByteWriter::text(const std::string& value) {
  varuint(value.size(), Field::count);
  for (char c : value) put(static_cast<uint8_t>(c), first_context(Field::text));
}

void ByteWriter::append(const ByteWriter& other) {
  bytes_ += other.bytes_;
  contexts_.insert(contexts_.end(), other.contexts_.begin(), other.contexts_.end());
}

uint8_t ByteReader::take(int context) {
  if (offset_ >= size_) fail("the payload ends inside a value");
  ++offset_;
  return source_.next(context);
}

uint8_t ByteReader::byte(Field field) { return take(first_context(field)); }
uint8_t ByteReader::byte(Field field, bool second) {
  return take(second ? continuation_context(field) : first_context(field));
}

uint8_t ByteReader::byte_in(int context) { return take(context); }

int64_t ByteReader::varsint_in(Field field, int first) { return unzigzag(varuint_from(field, first)); }
uint64_t ByteReader::varuint_in(Field field, int first) { return varuint_from(field, first); }

uint64_t ByteReader::varuint(Field field) { return varuint_from(field, first_context(field)); }

uint64_t ByteReader::varuint_from(Field field, int first) {
  const size_t start = offset_;
  uint64_t value = 0;
  for (int shift = 0;; shift += 7) {
    const uint8_t b = take(shift == 0 ? first : continuation_context(field));
    if (shift == 63 && b > 1) fail("varint larger than 64 bits", start);
    value |= static_cast<uint64_t>(b & 0x7F) << shift;
    if (!(b & 0x80)) return value;
    if (shift == 63) fail("varint longer than 10 bytes", start);
  }
}

int64_t ByteReader::varsint(Field field) { return unzigzag(varuint(field)); }

double ByteReader::float64() {
  uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= static_cast<uint64_t>(take(float_context(i))) << (8 * i);
  return bit_cast<double>(bits);
}

float ByteReader::float32() {
  uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) bits |= static_cast<uint32_t>(take(float_context(4 + i))) << (8 * i);
  return bit_cast<float>(bits);
}

std::string ByteReader::text() {
  const size_t n = count(1);
  std::string s(n, '\0');
  for (size_t i = 0; i < n; ++i) s[i] = static_cast<char>(take(first_context(Field::text)));
  return s;
}

size_t ByteReader::count(size_t min_bytes, Field field) {
  const size_t start = offset_;
  const uint64_t n = varuint(field);
  if (min_bytes > 0 && n > left() / min_bytes)
    fail("count " + std::to_string(n) + " cannot fit in the " + std::to_string(left()) + " bytes left", start);
  return static_cast<size_t>(n);
}

}  // namespace cadnurbs::cnb
