#include "core/binomial.hpp"

#include <vector>

namespace cadnurbs {

double binomial(int n, int k) {
  constexpr int kRows = 128;
  static const std::vector<double> triangle = [] {
    std::vector<double> t(kRows * kRows, 0.0);
    for (int r = 0; r < kRows; ++r) {
      t[r * kRows] = 1.0;
      for (int c = 1; c <= r; ++c) t[r * kRows + c] = t[(r - 1) * kRows + c - 1] + (c < r ? t[(r - 1) * kRows + c] : 0.0);
    }
    return t;
  }();
  if (n < kRows) return triangle[n * kRows + k];
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

}  // namespace cadnurbs
