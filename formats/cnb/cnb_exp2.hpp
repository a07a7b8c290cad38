#pragma once
// 2^x as every .cnb reader computes a weight of mode 2 (docs/cnb.md, "Weights"): the same bits on every
// platform, because the decoded weights place the surface, and the C libraries' exp2 differ in the last
// place (glibc's and musl's, the browser module's, do). Only +, -, x and rounding to an integer, in IEEE
// double without fused multiply-adds (compiled with -ffp-contract=off).
//
// Method: k = x rounded to the nearest integer, r = x - k in [-1/2, 1/2] (exact), t = r ln 2, e^t by its
// Taylor series to the t^17 term in Horner form (the remainder is below 2^-70 of the result), scaled by
// 2^k exactly. Accurate within a few units in the last place. x must be finite with |x| < 1000.
namespace cadnurbs::cnb {

double cnb_exp2(double x);

}  // namespace cadnurbs::cnb
