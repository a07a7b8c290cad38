#include "analysis/eval/span_quadrature.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <numbers>

namespace cadnurbs {
namespace {

constexpr double kCrowdedSpanInGaps = 4;

}  // namespace

// Newton on the Legendre polynomial from the Chebyshev guesses.
const QuadratureRule& gauss_legendre(int count) {
  static std::mutex mutex;
  static std::map<int, QuadratureRule> rules;
  std::lock_guard<std::mutex> lock(mutex);
  auto found = rules.find(count);
  if (found != rules.end()) return found->second;
  QuadratureRule rule;
  for (int i = 0; i < count; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (count + 0.5));
    double derivative = 1;
    for (int step = 0; step < 100; ++step) {
      double p0 = 1, p1 = x;  // Legendre P_0, P_1; recurrence up to P_count
      for (int k = 2; k <= count; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = count * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / derivative;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    rule.nodes.push_back(0.5 * (1 - x));
    rule.weights.push_back(1.0 / ((1 - x * x) * derivative * derivative));  // 2/(...) halved for [0, 1]
  }
  return rules.emplace(count, std::move(rule)).first->second;
}

const QuadratureRule& simpson() {
  static const QuadratureRule rule{{0.0, 0.5, 1.0}, {1.0 / 6, 4.0 / 6, 1.0 / 6}};
  return rule;
}

const QuadratureRule& fairness_rule(double length, double minimum_gap, int order) {
  return length <= kCrowdedSpanInGaps * minimum_gap ? simpson() : gauss_legendre(order);
}

}  // namespace cadnurbs
