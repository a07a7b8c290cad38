#include "formats/cnb/cnb_exp2.hpp"

#include <cmath>

namespace cadnurbs::cnb {

double cnb_exp2(double x) {
  const double k = std::nearbyint(x);  // the default rounding mode: to nearest, ties to even
  const double t = (x - k) * 0.69314718055994530942;  // |t| <= 0.3466
  // 1/i! for i = 17 down to 1, as decimal literals every compiler rounds alike.
  constexpr double inverse_factorials[] = {
      2.8114572543455207632e-15, 4.7794773323873852974e-14, 7.6471637318198164759e-13, 1.1470745597729724714e-11,
      1.6059043836821614599e-10, 2.0876756987868098979e-09, 2.5052108385441718775e-08, 2.7557319223985890653e-07,
      2.7557319223985890653e-06, 2.4801587301587301587e-05, 1.9841269841269841270e-04, 1.3888888888888888889e-03,
      8.3333333333333333333e-03, 4.1666666666666666667e-02, 1.6666666666666666667e-01, 5.0000000000000000000e-01,
      1.0};
  double sum = 0.0;
  for (double c : inverse_factorials) sum = sum * t + c;
  sum = sum * t + 1.0;
  return std::ldexp(sum, static_cast<int>(k));
}

}  // namespace cadnurbs::cnb
