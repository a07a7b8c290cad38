#include "core/knot_vector.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cadnurbs {

std::string knot_vector_fault(const std::vector<double>& knots, int order, int count) {
  std::ostringstream out;
  if (order < 2) {
    out << "order " << order << " is below 2";
    return out.str();
  }
  if (count < order) {
    out << count << " control points are too few for order " << order << " (need at least " << order << ")";
    return out.str();
  }
  if (static_cast<int>(knots.size()) != count + order) {
    out << knots.size() << " knots given, but " << count << " control points of order " << order << " need "
        << count + order;
    return out.str();
  }
  for (size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i])) {
      out << "knot " << i << " is not a finite number";
      return out.str();
    }
    if (i > 0 && knots[i] < knots[i - 1]) {
      out << "knot " << i << " (" << knots[i] << ") is smaller than knot " << i - 1 << " (" << knots[i - 1]
          << "); knots must not decrease";
      return out.str();
    }
  }
  // An interior knot repeated more than `order` times would split the curve; more than order-1 inside
  // the domain makes it discontinuous, which we allow (C-1 is legal), but never above order.
  int run = 1;
  for (size_t i = 1; i < knots.size(); ++i) {
    run = knots[i] == knots[i - 1] ? run + 1 : 1;
    if (run > order) {
      out << "knot value " << knots[i] << " is repeated " << run << " times, more than the order " << order;
      return out.str();
    }
  }
  if (!(knots[order - 1] < knots[count])) {
    out << "the domain [knot " << order - 1 << ", knot " << count << "] is empty";
    return out.str();
  }
  return {};
}

void basis_function_derivatives(const std::vector<double>& knots, int order, int span, double t, int max_derivative,
                                double* ders, int stride) {
  const int p = order - 1;
  const int nd = std::min(max_derivative, p);
  // Scratch on the stack up to kMaxStackOrder; heap only for higher orders (rare, and still correct).
  double ndu_stack[kMaxStackOrder * kMaxStackOrder], line_stack[4 * kMaxStackOrder];
  std::vector<double> heap;
  double* ndu = ndu_stack;
  double* line = line_stack;
  if (order > kMaxStackOrder) {
    heap.resize(static_cast<size_t>(order) * order + 4 * static_cast<size_t>(order));
    ndu = heap.data();
    line = heap.data() + static_cast<size_t>(order) * order;
  }
  auto N = [&](int i, int j) -> double& { return ndu[i * order + j]; };
  double* left = line;
  double* right = line + order;
  if (max_derivative == 0) {
    basis_function_values(knots.data(), order, span, t, ders, left, right);
    return;
  }
  double* a[2] = {line + 2 * order, line + 3 * order};
  N(0, 0) = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - knots[span + 1 - j];
    right[j] = knots[span + j] - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      N(j, r) = right[r + 1] + left[j - r];
      const double temp = N(r, j - 1) / N(j, r);
      N(r, j) = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N(j, j) = saved;
  }
  for (int k = 0; k <= max_derivative; ++k)
    for (int j = 0; j <= p; ++j) ders[k * stride + j] = k == 0 ? N(j, p) : 0.0;
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= nd; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / N(pk + 1, rk);
        d = a[s2][0] * N(rk, pk);
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / N(pk + 1, rk + j);
        d += a[s2][j] * N(rk + j, pk);
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / N(pk + 1, r);
        d += a[s2][k] * N(r, pk);
      }
      ders[k * stride + r] = d;
      std::swap(s1, s2);
    }
  }
  double factor = p;
  for (int k = 1; k <= nd; ++k) {
    for (int j = 0; j <= p; ++j) ders[k * stride + j] *= factor;
    factor *= (p - k);
  }
}

std::vector<std::vector<double>> basis_function_derivatives(const std::vector<double>& knots, int order,
                                                            int span, double t, int max_derivative) {
  std::vector<double> flat(static_cast<size_t>(max_derivative + 1) * order);
  basis_function_derivatives(knots, order, span, t, max_derivative, flat.data(), order);
  std::vector<std::vector<double>> ders(max_derivative + 1);
  for (int k = 0; k <= max_derivative; ++k) ders[k].assign(flat.begin() + k * order, flat.begin() + (k + 1) * order);
  return ders;
}

std::vector<double> clamped_uniform_knots(int order, int count) {
  std::vector<double> knots(count + order);
  const int spans = count - order + 1;
  for (int i = 0; i < count + order; ++i) {
    if (i < order) knots[i] = 0.0;
    else if (i >= count) knots[i] = 1.0;
    else knots[i] = static_cast<double>(i - order + 1) / spans;
  }
  return knots;
}

std::vector<KnotMultiplicity> knot_multiplicities(const std::vector<double>& knots) {
  std::vector<KnotMultiplicity> out;
  for (double k : knots) {
    if (!out.empty() && out.back().value == k) ++out.back().multiplicity;
    else out.push_back({k, 1});
  }
  return out;
}

std::vector<double> distinct_knots(const std::vector<double>& knots) {
  std::vector<double> out;
  for (const auto& km : knot_multiplicities(knots)) out.push_back(km.value);
  return out;
}

std::vector<double> domain_breaks(const std::vector<double>& knots, int order, int count) {
  const double a = knots[order - 1], b = knots[count];
  std::vector<double> out;
  for (const auto& km : knot_multiplicities(knots))
    if (km.value >= a && km.value <= b) out.push_back(km.value);
  return out;
}

std::vector<double> c0_knots(const std::vector<double>& knots, int order, int count) {
  const double a = knots[order - 1], b = knots[count];
  std::vector<double> out;
  for (const auto& km : knot_multiplicities(knots))
    if (km.value > a && km.value < b && km.multiplicity >= order - 1) out.push_back(km.value);
  return out;
}

}  // namespace cadnurbs
