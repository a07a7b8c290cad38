#pragma once
// The exact numbers of a .cnb payload: knot vectors (lossless: whole numbers, decimals, or raw float64)
// and weights (lossless: a table of the distinct values, one index per point), and the rounding of
// coordinates to a grid. docs/cnb.md, "Knot vector" and "Weights".
#include <cstdint>
#include <optional>
#include <vector>

#include "formats/cnb/cnb_stream.hpp"

namespace cadnurbs::cnb {

// round(x / step) as an integer. Throws std::invalid_argument when |x / step| > 2^52 (the step is too
// fine for the coordinate: a maximum deviation too small for the model's size) or x is not finite.
int64_t on_grid(double x, double step);

// The distinct values of the raw (mode 2) knot vectors met so far in a file, most recent first: a vector
// met again (the two pcurves of an edge, the u knots of neighbouring faces) is coded by its place here.
struct KnotCache {
  static constexpr size_t capacity = 64;
  std::vector<std::vector<double>> recent;
  void use(size_t index);                      // moves entry `index` to the front
  void add(const std::vector<double>& values);  // at the front, dropping the oldest beyond capacity
};

// Distinct values and multiplicities; values as whole numbers, as decimals n / 10^k that give back the
// same float64, as the place of the same values in the cache, or as raw float64.
void write_knots(ByteWriter& out, const std::vector<double>& knots, KnotCache& cache);
// Refuses (PayloadError) a vector whose multiplicities do not add up to `expected_count`, before
// allocating it, values that are not increasing, and a cache place that holds no such vector.
std::vector<double> read_knots(ByteReader& in, size_t expected_count, KnotCache& cache);

// The distinct weight values met so far in a file, most recent first (cos(θ/2) values repeat from face
// to face): a table entry met again is coded by its place here.
struct WeightCache {
  static constexpr size_t capacity = 64;
  std::vector<double> recent;
  void use(size_t index);
  void add(double value);
};

// Mode 0 (polynomial) or 1 (table of distinct float64 values, each new or from the cache; an index per
// point when there are two or more); with `log_step` > 0, mode 2: each weight as 2^(n·log_step), n predicted from the previous
// point's (a relative error of at most 2^(log_step/2) - 1).
void write_weights(ByteWriter& out, const std::vector<double>& weights, WeightCache& cache, double log_step = 0);
// `point_count` points; refuses a table larger than that, an index outside it, a weight <= 0 or not
// finite, a log step outside (0, 1).
std::vector<double> read_weights(ByteReader& in, size_t point_count, WeightCache& cache);

// A surface's weights as an outer product, w(i, j) = u[i]·v[j] (the weights of a swept, extruded or revolved
// surface are its profile's times its path's: 511 weights of a moulding from 73 + 7). Mode 3 writes the two
// factors as mode 1 tables and the reader multiplies them, so a weight comes back within a relative
// `relative_error` of the original (the products of rounded cos(θ/2) values are not bit for bit the rounded
// products).
struct WeightFactors {
  std::vector<double> u, v;   // u_count and v_count values > 0
  double relative_error = 0;  // largest |u[i]·v[j] - w(i, j)| / w(i, j)
};
// The factors taken from the row and column through the first largest weight (u[i] = w(i, j0),
// v[j] = w(i0, j) / w(i0, j0)), so that they are the file's own values where the largest is 1; nothing
// when the weights hold fewer than two distinct values, the factors as many numbers as the weights, or a
// product is off by more than `largest_relative_error`. Weights in VRML order (u fastest).
std::optional<WeightFactors> weight_factors(const std::vector<double>& weights, int u_count, int v_count,
                                            double largest_relative_error);
// Mode 3.
void write_weight_factors(ByteWriter& out, const WeightFactors& factors, WeightCache& cache);
// A surface's weights, modes 0 to 3 (mode 3 only where `factors_allowed`: format version 6 on); refuses
// what read_weights refuses, per factor.
std::vector<double> read_surface_weights(ByteReader& in, size_t u_count, size_t v_count, WeightCache& cache,
                                         bool factors_allowed);

// How many different values `weights` holds.
size_t distinct_count(const std::vector<double>& weights);

// A float64 kept exactly, coded small where it is a short decimal (a placement's 0, ±1, -33.02): a
// varuint k + 1 and a varsint n when n / 10^k gives it back bit for bit (the smallest such k in 0..17),
// else 0 and the raw float64. The reader refuses a k above 17 and a value that is not finite.
void write_exact_number(ByteWriter& out, double value);
double read_exact_number(ByteReader& in);
// The smallest number of three significant digits at or above `value` > 0, as read_exact_number gives it
// back, so that it codes in about 3 bytes instead of 8; `value` itself where no such decimal has an
// exponent in 0..17 (below 1e-15, or from 1000 on).
double short_decimal_at_least(double value);

// Orders: refused above this before anything is allocated.
constexpr uint64_t largest_order = 64;
// An order (of a surface direction, a curve or a trimming curve); refuses (PayloadError) one outside
// 2..largest_order.
uint64_t read_order(ByteReader& in);

}  // namespace cadnurbs::cnb
