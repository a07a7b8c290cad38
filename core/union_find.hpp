#pragma once
// Disjoint sets over 0..n-1 (union by smaller root, path halving): the classes of "the same vertex" or
// "the same edge" that sewing and shared-edge tessellation build from pairwise matches.
#include <algorithm>
#include <vector>

namespace cadnurbs {

class UnionFind {
 public:
  explicit UnionFind(size_t n = 0) : parent_(n) {
    for (size_t i = 0; i < n; ++i) parent_[i] = static_cast<int>(i);
  }
  // A new singleton class; returns its element.
  int add() {
    parent_.push_back(static_cast<int>(parent_.size()));
    return parent_.back();
  }
  // The class's root: its smallest element.
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  size_t size() const { return parent_.size(); }
  // Consumes the sets; returns each element's class number, classes numbered 0, 1, ... in order of
  // their smallest elements. In place, O(n): a parent is never larger than its child, so one increasing
  // pass turns parents into roots and a second turns roots into numbers.
  std::vector<int> into_class_numbers() && {
    std::vector<int> label = std::move(parent_);
    const int n = static_cast<int>(label.size());
    for (int x = 0; x < n; ++x) label[x] = label[label[x]];
    int classes = 0;
    for (int x = 0; x < n; ++x) label[x] = label[x] == x ? classes++ : label[label[x]];
    return label;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace cadnurbs
