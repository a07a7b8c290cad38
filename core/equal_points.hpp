#pragma once
// Points with bitwise-equal coordinates given one number, in order of first occurrence: how the STL reader
// and weld_vertices turn the repeated corners of a triangle soup into shared vertices in O(n) expected.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace cadnurbs {

class EqualPoints {
 public:
  // Returns p's number: that of the equal point added before, else the next number, with p appended to
  // points(). Equality is of the bits (0.0 and -0.0 are two points; a NaN is never equal to itself).
  int add(const Eigen::Vector3d& p);

  // Room for `count` points without regrowing (a hint; more may be added).
  void reserve(std::size_t count);

  const std::vector<Eigen::Vector3d>& points() const { return points_; }
  std::vector<Eigen::Vector3d> take_points() && { return std::move(points_); }

 private:
  struct Slot {
    std::uint32_t hash = 0;
    int point = -1;
  };
  static std::uint64_t hash(const Eigen::Vector3d& p);
  void grow();
  void rehash(std::size_t size);  // a power of two, at least twice the points

  std::vector<Eigen::Vector3d> points_;
  std::vector<Slot> slots_ = std::vector<Slot>(1024);  // at most half full, so probe runs stay short
};

}  // namespace cadnurbs
