#include "fit_path/path_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace cadnurbs::test {

namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.7g", x);
  return text;
}

// Keys as a file holds them (7 digits), so that the paths the tests compare are the ones written.
double stored(double x) { return std::stod(number(x)); }

}  // namespace

KeyframePath circle_path(int count, double radius) {
  KeyframePath path;
  for (int i = 0; i < count; ++i) {
    const double t = stored(double(i) / (count - 1)), a = 2 * M_PI * t;
    path.keys.push_back(t);
    path.values.emplace_back(stored(radius * std::cos(a)), stored(radius * std::sin(a)), 0.0);
  }
  return path;
}

KeyframePath helix_path(int count, double radius, double turns, double rise) {
  KeyframePath path;
  for (int i = 0; i < count; ++i) {
    const double t = stored(double(i) / (count - 1)), a = 2 * M_PI * turns * t;
    path.keys.push_back(t);
    path.values.emplace_back(stored(radius * std::cos(a)), stored(radius * std::sin(a)), stored(rise * turns * t));
  }
  return path;
}

KeyframePath figure_eight_path(int count, double size) {
  KeyframePath path;
  for (int i = 0; i < count; ++i) {
    const double s = double(i) / (count - 1);
    // Uneven keys: the spacing follows 1 + 0.66 sin(2 pi s), between 0.34 and 1.66 of the mean.
    const double t = stored(std::clamp(s + 0.66 * (1 - std::cos(2 * M_PI * s)) / (2 * M_PI), 0.0, 1.0));
    const double a = 2 * M_PI * t;
    path.keys.push_back(t);
    path.values.emplace_back(stored(0.5 * size * std::sin(a)), stored(0.5 * size * std::sin(a) * std::cos(a)), 0.0);
  }
  return path;
}

KeyframePath noisy_circle_path(int count, double radius, double amplitude) {
  KeyframePath path = circle_path(count, radius);
  std::mt19937 random(20261127);
  std::uniform_real_distribution<double> noise(-amplitude, amplitude);
  for (auto& v : path.values)
    for (int c = 0; c < 3; ++c) v[c] = stored(v[c] + noise(random));
  return path;
}

Eigen::Vector3d path_at(const KeyframePath& path, double t) {
  if (t <= path.keys.front()) return path.values.front();
  if (t >= path.keys.back()) return path.values.back();
  const size_t i = std::upper_bound(path.keys.begin(), path.keys.end(), t) - path.keys.begin();
  const double s = (t - path.keys[i - 1]) / (path.keys[i] - path.keys[i - 1]);
  return (1 - s) * path.values[i - 1] + s * path.values[i];
}

double sampled_path_error(const NurbsCurve& curve, const KeyframePath& path) {
  double worst = 0;
  for (size_t i = 0; i < path.keys.size(); ++i) {
    worst = std::max(worst, (curve_point(curve, path.keys[i]) - path.values[i]).norm());
    if (i > 0) {
      const double t = 0.5 * (path.keys[i - 1] + path.keys[i]);
      worst = std::max(worst, (curve_point(curve, t) - path_at(path, t)).norm());
    }
  }
  return worst;
}

std::string keys_text(const KeyframePath& path) {
  std::string out;
  for (double k : path.keys) out += number(k) + " ";
  return out;
}

std::string key_values_text(const KeyframePath& path) {
  std::string out;
  for (const auto& v : path.values) out += number(v.x()) + " " + number(v.y()) + " " + number(v.z()) + ",\n";
  return out;
}

}  // namespace cadnurbs::test
