// The portable 2^x of the weights of mode 2 (formats/cnb/cnb_exp2.hpp): exact at integers, within a few
// units in the last place of the C library's exp2 elsewhere.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/cnb/cnb_exp2.hpp"

using cadnurbs::cnb::cnb_exp2;

TEST(CnbExp2, ExactAtIntegers) {
  for (int k = -60; k <= 60; ++k) EXPECT_EQ(cnb_exp2(k), std::ldexp(1.0, k)) << k;
}

TEST(CnbExp2, WithinFourUnitsInTheLastPlaceOfTheLibrary) {
  double worst = 0;
  for (int i = -200000; i <= 200000; ++i) {
    const double x = i * 3.7e-4;  // the range of weights' exponents a writer uses, at an odd step
    const double ours = cnb_exp2(x), library = std::exp2(x);
    worst = std::max(worst, std::abs(ours - library) / (std::nextafter(library, INFINITY) - library));
  }
  EXPECT_LE(worst, 4.0);
}

TEST(CnbExp2, HalfwayAndNegativeHalves) {
  EXPECT_NEAR(cnb_exp2(0.5), std::sqrt(2.0), 4e-16);
  EXPECT_NEAR(cnb_exp2(-0.5), 1 / std::sqrt(2.0), 4e-16);
  EXPECT_NEAR(cnb_exp2(10.5), 1024 * std::sqrt(2.0), 1024 * 4e-16);
}
