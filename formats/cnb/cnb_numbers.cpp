#include "formats/cnb/cnb_numbers.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "formats/cnb/cnb_exp2.hpp"

namespace cadnurbs::cnb {

int64_t on_grid(double x, double step) {
  const double n = std::round(x / step);
  if (!std::isfinite(n) || std::abs(n) > 0x1p52)
    throw std::invalid_argument("cnb: coordinate " + std::to_string(x) + " is " + std::to_string(std::abs(x / step)) +
                                " steps of " + std::to_string(step) + " from 0; the maximum deviation is too small for the model");
  return static_cast<int64_t>(n);
}

namespace {

enum KnotMode : uint8_t { whole = 0, decimal = 1, raw = 2, cached = 3 };

// The values as integers n_i with n_i / 10^k == value bitwise, for the smallest k in 0..17 that works.
bool as_decimals(const std::vector<double>& values, int& k, std::vector<int64_t>& n) {
  for (k = 0; k <= 17; ++k) {
    const double scale = std::pow(10.0, k);  // exact up to 10^22
    n.clear();
    bool ok = true;
    for (double v : values) {
      const double m = std::round(v * scale);
      if (!(std::abs(m) < 0x1p53) || m / scale != v) { ok = false; break; }
      n.push_back(static_cast<int64_t>(m));
    }
    if (ok) return true;
  }
  return false;
}

}  // namespace

void write_exact_number(ByteWriter& out, double value) {
  int k = 0;
  std::vector<int64_t> n;
  if (as_decimals({value}, k, n)) {
    out.varuint(static_cast<uint64_t>(k) + 1, Field::raw);
    out.varsint(n[0], Field::raw);
  } else {
    out.varuint(0, Field::raw);
    out.float64(value);
  }
}

double short_decimal_at_least(double value) {
  if (!(value > 0) || !std::isfinite(value)) return value;
  const int k = 2 - static_cast<int>(std::floor(std::log10(value)));
  if (k < 0 || k > 17) return value;
  const double scale = std::pow(10.0, static_cast<double>(k));  // as read_exact_number divides
  int64_t n = static_cast<int64_t>(std::ceil(value * scale));
  while (static_cast<double>(n) / scale < value) ++n;
  return static_cast<double>(n) / scale;
}

double read_exact_number(ByteReader& in) {
  const size_t at = in.offset();
  const uint64_t tag = in.varuint(Field::raw);
  if (tag > 18) in.fail("decimal exponent " + std::to_string(tag - 1) + " outside 0..17", at);
  double value;
  if (tag == 0) {
    value = in.float64();
  } else {
    const size_t n_at = in.offset();
    const int64_t n = in.varsint(Field::raw);
    if (std::abs(static_cast<double>(n)) >= 0x1p53) in.fail("decimal numerator out of range", n_at);
    value = static_cast<double>(n) / std::pow(10.0, static_cast<double>(tag - 1));
  }
  if (!std::isfinite(value)) in.fail("a number that is not finite", at);
  return value;
}

void KnotCache::use(size_t index) { std::rotate(recent.begin(), recent.begin() + index, recent.begin() + index + 1); }

void KnotCache::add(const std::vector<double>& values) {
  recent.insert(recent.begin(), values);
  if (recent.size() > capacity) recent.pop_back();
}

void write_knots(ByteWriter& out, const std::vector<double>& knots, KnotCache& cache) {
  std::vector<double> values;
  std::vector<uint64_t> multiplicity;
  for (double t : knots) {
    if (!values.empty() && t == values.back()) ++multiplicity.back();
    else { values.push_back(t); multiplicity.push_back(1); }
  }
  out.varuint(values.size(), Field::count);
  int k = 0;
  std::vector<int64_t> n;
  if (as_decimals(values, k, n)) {
    if (k == 0) out.byte(whole, Field::knot);
    else { out.byte(decimal, Field::knot); out.byte(static_cast<uint8_t>(k), Field::knot); }
    out.varsint(n[0], Field::knot);
    for (size_t i = 1; i < n.size(); ++i) out.varuint(static_cast<uint64_t>(n[i] - n[i - 1] - 1), Field::knot);
  } else if (const auto hit = std::find(cache.recent.begin(), cache.recent.end(), values); hit != cache.recent.end()) {
    out.byte(cached, Field::knot);
    const size_t index = static_cast<size_t>(hit - cache.recent.begin());
    out.varuint(index, Field::knot);
    cache.use(index);
  } else {
    out.byte(raw, Field::knot);
    for (double v : values) out.float64(v);
    cache.add(values);
  }
  for (uint64_t m : multiplicity) out.varuint(m - 1, Field::count);
}

std::vector<double> read_knots(ByteReader& in, size_t expected_count, KnotCache& cache) {
  const size_t start = in.offset();
  const size_t m = in.count(2);
  if (m == 0 || m > expected_count) in.fail(std::to_string(m) + " distinct knots for a vector of " + std::to_string(expected_count), start);
  const size_t mode_at = in.offset();
  const uint8_t mode = in.byte(Field::knot);
  std::vector<double> values;
  values.reserve(m);
  if (mode == whole || mode == decimal) {
    int k = 0;
    if (mode == decimal) {
      k = in.byte(Field::knot);
      if (k < 1 || k > 17) in.fail("decimal knot exponent " + std::to_string(k) + " outside 1..17", mode_at + 1);
    }
    const double scale = std::pow(10.0, k);
    int64_t n = in.varsint(Field::knot);
    for (size_t i = 0; i < m; ++i) {
      if (i > 0) {
        const size_t at = in.offset();
        const uint64_t step = in.varuint(Field::knot);
        // Numerators lie in (-2^53, 2^53), so a difference up to 2^54 is legal (a knot vector from -a to a).
        if (step >= 0x1p54 || static_cast<double>(n) + static_cast<double>(step) + 1 >= 0x1p53)
          in.fail("knot difference " + std::to_string(step) + " out of range", at);
        n += static_cast<int64_t>(step) + 1;
      }
      if (std::abs(static_cast<double>(n)) >= 0x1p53) in.fail("knot numerator out of range", in.offset());
      values.push_back(static_cast<double>(n) / scale);
    }
  } else if (mode == raw) {
    for (size_t i = 0; i < m; ++i) {
      const size_t at = in.offset();
      values.push_back(in.float64());
      if (!std::isfinite(values.back()) || (i > 0 && !(values[i] > values[i - 1])))
        in.fail("knot " + std::to_string(values.back()) + " is not finite or not above the previous one", at);
    }
    cache.add(values);
  } else if (mode == cached) {
    const size_t at = in.offset();
    const uint64_t index = in.varuint(Field::knot);
    if (index >= cache.recent.size() || cache.recent[index].size() != m)
      in.fail("no earlier knot vector of " + std::to_string(m) + " values at cache place " + std::to_string(index), at);
    values = cache.recent[index];
    cache.use(index);
  } else {
    in.fail("unknown knot mode " + std::to_string(mode), mode_at);
  }
  std::vector<uint64_t> multiplicity(m);
  uint64_t total = 0;
  for (size_t i = 0; i < m; ++i) {
    const size_t at = in.offset();
    multiplicity[i] = in.varuint(Field::count) + 1;
    if (multiplicity[i] == 0 || multiplicity[i] > expected_count - total)
      in.fail("knot multiplicities exceed the " + std::to_string(expected_count) + " knots the net needs", at);
    total += multiplicity[i];
  }
  if (total != expected_count)
    in.fail("knot multiplicities add up to " + std::to_string(total) + ", the net needs " + std::to_string(expected_count), start);
  std::vector<double> knots;
  knots.reserve(expected_count);
  for (size_t i = 0; i < m; ++i) knots.insert(knots.end(), multiplicity[i], values[i]);
  return knots;
}

uint64_t read_order(ByteReader& in) {
  const size_t at = in.offset();
  const uint64_t order = in.varuint(Field::count);
  if (order < 2 || order > largest_order) in.fail("order " + std::to_string(order) + " outside 2.." + std::to_string(largest_order), at);
  return order;
}

size_t distinct_count(const std::vector<double>& weights) {
  std::vector<double> sorted = weights;
  std::sort(sorted.begin(), sorted.end());
  return static_cast<size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
}

void WeightCache::use(size_t index) { std::rotate(recent.begin(), recent.begin() + index, recent.begin() + index + 1); }

void WeightCache::add(double value) {
  recent.insert(recent.begin(), value);
  if (recent.size() > capacity) recent.pop_back();
}

namespace {
// Mode 1 after its mode byte: the table of distinct values, then (for two or more) an index per point.
void write_weight_table(ByteWriter& out, const std::vector<double>& weights, WeightCache& cache) {
  std::vector<double> table;
  std::vector<uint64_t> index;
  index.reserve(weights.size());
  for (double w : weights) {
    size_t i = 0;
    while (i < table.size() && table[i] != w) ++i;  // tables are short: cos(θ/2) values and 1
    if (i == table.size()) table.push_back(w);
    index.push_back(i);
  }
  out.varuint(table.size(), Field::count);
  for (double w : table) {
    const auto hit = std::find(cache.recent.begin(), cache.recent.end(), w);
    if (hit == cache.recent.end()) {
      out.varuint(0, Field::weight);
      out.float64(w);
      cache.add(w);
    } else {
      const size_t index = static_cast<size_t>(hit - cache.recent.begin());
      out.varuint(index + 1, Field::weight);
      cache.use(index);
    }
  }
  if (table.size() > 1)
    for (uint64_t i : index) out.varuint(i, Field::weight);
}

std::vector<double> read_weight_table(ByteReader& in, size_t point_count, WeightCache& cache) {
  const size_t start = in.offset();
  const size_t t = in.count(1);
  if (t == 0 || t > point_count) in.fail(std::to_string(t) + " distinct weights for " + std::to_string(point_count) + " points", start);
  std::vector<double> table(t);
  for (auto& w : table) {
    const size_t at = in.offset();
    const uint64_t place = in.varuint(Field::weight);
    if (place == 0) {
      w = in.float64();
      if (!(w > 0) || !std::isfinite(w)) in.fail("weight " + std::to_string(w) + " is not positive and finite", at);
      cache.add(w);
    } else {
      if (place > cache.recent.size()) in.fail("weight cache place " + std::to_string(place) + " beyond the " + std::to_string(cache.recent.size()) + " weights met", at);
      w = cache.recent[place - 1];
      cache.use(place - 1);
    }
  }
  if (t == 1) return std::vector<double>(point_count, table[0]);
  if (point_count > in.left()) in.fail(std::to_string(point_count) + " weight indices cannot fit in the " + std::to_string(in.left()) + " bytes left");
  std::vector<double> weights(point_count);
  for (auto& w : weights) {
    const size_t at = in.offset();
    const uint64_t i = in.varuint(Field::weight);
    if (i >= t) in.fail("weight index " + std::to_string(i) + " outside the table of " + std::to_string(t), at);
    w = table[i];
  }
  return weights;
}

// Modes 0 to 2, the mode byte (at `mode_at`) read.
std::vector<double> read_weights_of_mode(ByteReader& in, uint8_t mode, size_t mode_at, size_t point_count, WeightCache& cache) {
  if (mode == 0) return {};
  if (mode == 2) {
    const size_t step_at = in.offset();
    const double step = in.float64();
    if (!(step > 0 && step < 1)) in.fail("weight log step " + std::to_string(step) + " outside (0, 1)", step_at);
    if (point_count > in.left()) in.fail(std::to_string(point_count) + " weights cannot fit in the " + std::to_string(in.left()) + " bytes left");
    std::vector<double> weights(point_count);
    int64_t n = 0;
    for (auto& w : weights) {
      const size_t at = in.offset();
      const int64_t r = in.varsint(Field::weight);
      if (std::abs(static_cast<double>(r)) > 0x1p52 || std::abs(static_cast<double>(n) + static_cast<double>(r)) > 0x1p52)
        in.fail("weight exponent out of range", at);
      n += r;
      w = cnb_exp2(static_cast<double>(n) * step);
      if (!(w > 0) || !std::isfinite(w)) in.fail("weight 2^(" + std::to_string(n) + " x " + std::to_string(step) + ") is not positive and finite", at);
    }
    return weights;
  }
  if (mode != 1) in.fail("unknown weight mode " + std::to_string(mode), mode_at);
  return read_weight_table(in, point_count, cache);
}
}  // namespace

void write_weights(ByteWriter& out, const std::vector<double>& weights, WeightCache& cache, double log_step) {
  if (weights.empty()) { out.byte(0, Field::weight); return; }
  if (log_step > 0) {
    out.byte(2, Field::weight);
    out.float64(log_step);
    int64_t previous = 0;
    for (double w : weights) {
      const int64_t n = on_grid(std::log2(w), log_step);
      out.varsint(n - previous, Field::weight);
      previous = n;
    }
    return;
  }
  out.byte(1, Field::weight);
  write_weight_table(out, weights, cache);
}

std::vector<double> read_weights(ByteReader& in, size_t point_count, WeightCache& cache) {
  const size_t mode_at = in.offset();
  const uint8_t mode = in.byte(Field::weight);
  return read_weights_of_mode(in, mode, mode_at, point_count, cache);
}

std::optional<WeightFactors> weight_factors(const std::vector<double>& weights, int u_count, int v_count,
                                            double largest_relative_error) {
  const size_t n = static_cast<size_t>(u_count) * static_cast<size_t>(v_count);
  if (u_count < 1 || v_count < 1 || weights.size() != n || size_t(u_count) + size_t(v_count) >= n ||
      distinct_count(weights) < 2)
    return std::nullopt;
  const size_t largest = static_cast<size_t>(std::max_element(weights.begin(), weights.end()) - weights.begin());
  const int i0 = static_cast<int>(largest % u_count), j0 = static_cast<int>(largest / u_count);
  WeightFactors f;
  for (int i = 0; i < u_count; ++i) f.u.push_back(weights[i + static_cast<size_t>(j0) * u_count]);
  const double corner = weights[largest];
  for (int j = 0; j < v_count; ++j) {
    const double w = weights[i0 + static_cast<size_t>(j) * u_count];
    f.v.push_back(w == corner ? 1.0 : w / corner);
  }
  for (int j = 0; j < v_count; ++j)
    for (int i = 0; i < u_count; ++i) {
      const double w = weights[i + static_cast<size_t>(j) * u_count];
      if (!(w > 0) || !std::isfinite(w)) return std::nullopt;
      f.relative_error = std::max(f.relative_error, std::abs(f.u[i] * f.v[j] - w) / w);
    }
  if (!(f.relative_error <= largest_relative_error)) return std::nullopt;
  return f;
}

void write_weight_factors(ByteWriter& out, const WeightFactors& factors, WeightCache& cache) {
  out.byte(3, Field::weight);
  write_weight_table(out, factors.u, cache);
  write_weight_table(out, factors.v, cache);
}

std::vector<double> read_surface_weights(ByteReader& in, size_t u_count, size_t v_count, WeightCache& cache,
                                         bool factors_allowed) {
  const size_t mode_at = in.offset();
  const uint8_t mode = in.byte(Field::weight);
  if (mode != 3 || !factors_allowed) return read_weights_of_mode(in, mode, mode_at, u_count * v_count, cache);
  const std::vector<double> u = read_weight_table(in, u_count, cache);
  const std::vector<double> v = read_weight_table(in, v_count, cache);
  std::vector<double> weights;
  weights.reserve(u_count * v_count);
  for (size_t j = 0; j < v_count; ++j)
    for (size_t i = 0; i < u_count; ++i) {
      const double w = u[i] * v[j];
      if (!(w > 0) || !std::isfinite(w)) in.fail("weight " + std::to_string(u[i]) + " x " + std::to_string(v[j]) + " is not positive and finite", mode_at);
      weights.push_back(w);
    }
  return weights;
}

}  // namespace cadnurbs::cnb
