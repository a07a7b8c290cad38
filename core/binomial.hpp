#pragma once
// C(n, k), the binomial coefficient, as a double: a table up to n = 127 (products of Bézier pieces of
// degree up to 25 stay below it), a product loop beyond. 0 <= k <= n.
namespace cadnurbs {

double binomial(int n, int k);

}  // namespace cadnurbs
