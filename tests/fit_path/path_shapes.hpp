#pragma once
// Keyframe paths the fit-path tests make: keys in [0, 1] and one position per key.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/nurbs_curve.hpp"

namespace cadnurbs::test {

struct KeyframePath {
  std::vector<double> keys;
  std::vector<Eigen::Vector3d> values;
};

// A circle of `radius` in the xy plane, once round, `count` evenly spaced keys on [0, 1].
KeyframePath circle_path(int count, double radius);
// A helix of `radius`, `turns` turns rising `rise` per turn, `count` evenly spaced keys.
KeyframePath helix_path(int count, double radius, double turns, double rise);
// A figure-eight (lemniscate of Gerono, `size` across) with unevenly spaced keys: the key spacing
// varies by a factor of about 5 along the path.
KeyframePath figure_eight_path(int count, double size);
// circle_path with every coordinate moved by uniform noise in [-amplitude, amplitude] (fixed seed), as
// a recorded path would be.
KeyframePath noisy_circle_path(int count, double radius, double amplitude);

// The path f(t) of the interpolator: linear between keys, constant outside them.
Eigen::Vector3d path_at(const KeyframePath& path, double t);

// The largest distance of `curve` from the path at its keys and halfway between them (an attained
// value, not a bound).
double sampled_path_error(const NurbsCurve& curve, const KeyframePath& path);

// The interpolator's key and keyValue fields' numbers as a file writer would put them, 7 significant
// digits ("key [...] keyValue [...]" without the brackets' field names).
std::string keys_text(const KeyframePath& path);
std::string key_values_text(const KeyframePath& path);

}  // namespace cadnurbs::test
