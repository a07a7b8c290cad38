#include "formats/vrml/node_text.hpp"

#include <stdexcept>

namespace cadnurbs {

namespace {

template <class Vector>
void append_tuples(std::string& out, const std::vector<Vector>& tuples, const NumberPrecision& precision) {
  for (size_t i = 0; i < tuples.size(); ++i) {
    if (i > 0) out.push_back('\n');
    for (int k = 0; k < tuples[i].size(); ++k) {
      if (k > 0) out.push_back(' ');
      append_number(out, tuples[i][k], precision);
    }
  }
}

void append_vector(std::string& out, const Eigen::Vector3d& v, const NumberPrecision& precision) {
  for (int k = 0; k < 3; ++k) {
    if (k > 0) out.push_back(' ');
    append_number(out, v[k], precision);
  }
}

}  // namespace

void append_numeric_value(std::string& out, const FieldValue& value, const NumberPrecision& precision) {
  if (const auto* d = std::get_if<double>(&value)) {
    append_number(out, *d, precision);
  } else if (const auto* i = std::get_if<int>(&value)) {
    out += std::to_string(*i);
  } else if (const auto* mf = std::get_if<MFFloat>(&value)) {
    for (size_t k = 0; k < mf->values.size(); ++k) {
      if (k > 0) out.push_back(' ');
      append_number(out, mf->values[k], precision);
    }
  } else if (const auto* mi = std::get_if<MFInt32>(&value)) {
    for (size_t k = 0; k < mi->values.size(); ++k) {
      if (k > 0) out.push_back(mi->values[k - 1] == -1 ? '\n' : ' ');
      out += std::to_string(mi->values[k]);
    }
  } else if (const auto* v2 = std::get_if<MFVec2f>(&value)) {
    append_tuples(out, v2->values, precision);
  } else if (const auto* v3 = std::get_if<MFVec3f>(&value)) {
    append_tuples(out, v3->values, precision);
  } else if (const auto* c = std::get_if<SFColor>(&value)) {
    append_vector(out, c->value, precision);
  } else if (const auto* v = std::get_if<SFVec3f>(&value)) {
    append_vector(out, v->value, precision);
  } else if (const auto* r = std::get_if<SFRotation>(&value)) {
    append_vector(out, r->axis, precision);
    out.push_back(' ');
    append_number(out, r->angle, precision);
  } else {
    throw std::logic_error("append_numeric_value: not a numeric value");
  }
}

bool is_numeric_value(const FieldValue& value) {
  return std::holds_alternative<double>(value) || std::holds_alternative<int>(value) ||
         std::holds_alternative<MFFloat>(value) || std::holds_alternative<MFInt32>(value) ||
         std::holds_alternative<MFVec2f>(value) || std::holds_alternative<MFVec3f>(value) ||
         std::holds_alternative<SFColor>(value) || std::holds_alternative<SFVec3f>(value) ||
         std::holds_alternative<SFRotation>(value);
}

size_t number_count(const FieldValue& value) {
  if (const auto* mf = std::get_if<MFFloat>(&value)) return mf->values.size();
  if (const auto* mi = std::get_if<MFInt32>(&value)) return mi->values.size();
  if (const auto* v2 = std::get_if<MFVec2f>(&value)) return 2 * v2->values.size();
  if (const auto* v3 = std::get_if<MFVec3f>(&value)) return 3 * v3->values.size();
  if (std::holds_alternative<SFColor>(value) || std::holds_alternative<SFVec3f>(value)) return 3;
  if (std::holds_alternative<SFRotation>(value)) return 4;
  return 1;
}

std::string quoted_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out.push_back('\\');
    out.push_back(c);
  }
  out.push_back('"');
  return out;
}

}  // namespace cadnurbs
