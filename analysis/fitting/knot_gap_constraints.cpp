#include "analysis/fitting/knot_gap_constraints.hpp"

#include <algorithm>
#include <limits>

namespace cadnurbs {
namespace {

// Pools the direction's components at chain positions first..last (0 and size + 1 are the fixed
// ends, whose component is 0) into non-decreasing block means.
void pool_chain(Eigen::VectorXd& d, int offset, int size, int first, int last) {
  struct Block {
    double sum;
    int count;
    bool fixed;  // holds an end of the domain
    double mean() const { return fixed ? 0.0 : sum / count; }
  };
  std::vector<Block> blocks;
  for (int p = first; p <= last; ++p) {
    const bool fixed = p == 0 || p == size + 1;
    blocks.push_back({fixed ? 0.0 : d[offset + p - 1], 1, fixed});
    while (blocks.size() >= 2 && blocks[blocks.size() - 2].mean() > blocks.back().mean()) {
      Block top = blocks.back();
      blocks.pop_back();
      blocks.back().sum += top.sum;
      blocks.back().count += top.count;
      blocks.back().fixed = blocks.back().fixed || top.fixed;
    }
  }
  int p = first;
  for (const Block& block : blocks) {
    for (int k = 0; k < block.count; ++k, ++p) {
      if (p != 0 && p != size + 1) d[offset + p - 1] = block.mean();
    }
  }
}

}  // namespace

std::vector<double> averaged_knots(const std::vector<double>& parameters, int order, int count) {
  const int degree = order - 1;
  std::vector<double> knots(count + order, 0.0);
  std::fill(knots.end() - order, knots.end(), 1.0);
  const double d = static_cast<double>(parameters.size()) / (count - degree);
  for (int j = 1; j < count - degree; ++j) {
    const int i = static_cast<int>(j * d);
    const double alpha = j * d - i;
    knots[degree + j] = (1 - alpha) * parameters[i - 1] + alpha * parameters[i];
  }
  return knots;
}

void keep_knot_gaps(std::vector<double>& knots, int order, int count, double gap) {
  for (int i = order; i < count; ++i) knots[i] = std::max(knots[i], knots[i - 1] + gap);
  for (int i = count - 1; i >= order; --i) knots[i] = std::min(knots[i], knots[i + 1] - gap);
}

double KnotGapBlock::max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const {
  double bound = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= size && size > 0; ++i) {
    const double left = i == 0 ? 0.0 : x[offset + i - 1], right = i == size ? scale : x[offset + i];
    const double d_left = i == 0 ? 0.0 : d[offset + i - 1], d_right = i == size ? 0.0 : d[offset + i];
    if (d_left - d_right > 0) bound = std::min(bound, std::max(0.0, right - left - gap) / (d_left - d_right));
  }
  return bound;
}

void KnotGapBlock::adjust(const Eigen::VectorXd& x, Eigen::VectorXd& d) const {
  const double active = 1e-9 * gap;
  auto position = [&](int p) { return p == 0 ? 0.0 : p == size + 1 ? scale : x[offset + p - 1]; };
  int i = 0;
  while (size > 0 && i <= size + 1) {
    // A chain of positions i..last (0 and size + 1 are the fixed ends) joined by active gaps.
    int last = i;
    while (last <= size && position(last + 1) - position(last) - gap <= active) ++last;
    if (last > i) pool_chain(d, offset, size, i, last);
    i = last + 1;
  }
}

}  // namespace cadnurbs
