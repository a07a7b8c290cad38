#include "formats/3dm/object_checks.hpp"

#include <variant>

#include "core/geometry_error.hpp"
#include "core/number_format.hpp"
#include "formats/3dm/rhino_object.hpp"

namespace cadnurbs::rhino {

void refuse(const ArchiveReader& reader, const char* class_name, const std::string& reason) {
  reader.fail(std::string(class_name) + ": " + reason);
}

int expect_major_version(ArchiveReader& reader, const char* class_name, int major) {
  const auto [found_major, minor] = reader.chunk_version();
  if (found_major != major)
    refuse(reader, class_name,
           "chunk version " + std::to_string(found_major) + "." + std::to_string(minor) + " (only " +
               std::to_string(major) + ".x is read)");
  return minor;
}

std::size_t read_count(ArchiveReader& reader, const char* class_name, std::size_t element_size,
                       const std::string& what) {
  const std::int32_t count = reader.i32();
  if (count < 0) refuse(reader, class_name, what + " count " + std::to_string(count) + " is negative");
  const std::size_t left = reader.bytes_left();
  if (static_cast<std::uint64_t>(count) * element_size > left)
    refuse(reader, class_name,
           std::to_string(count) + " " + what + " of " + std::to_string(element_size) + " bytes need more than the " +
               std::to_string(left) + " bytes left");
  return static_cast<std::size_t>(count);
}

int expect_dimension(const ArchiveReader& reader, const char* class_name, int dimension) {
  if (dimension != 2 && dimension != 3)
    refuse(reader, class_name, "dimension " + std::to_string(dimension) + " is neither 2 nor 3");
  return dimension;
}

void expect_order_and_count(const ArchiveReader& reader, const char* class_name, const std::string& direction,
                            int order, int count) {
  const std::string prefix = direction.empty() ? "" : direction + " ";
  if (order < 2) refuse(reader, class_name, prefix + "order " + std::to_string(order) + " is below 2");
  if (count < order)
    refuse(reader, class_name, std::to_string(count) + " control points" + (direction.empty() ? "" : " in " + direction) +
                                   " are too few for order " + std::to_string(order));
}

namespace {

template <class Geometry>
Geometry validated(const ArchiveReader& reader, const char* class_name, Geometry geometry) {
  try {
    validate(geometry, class_name);
  } catch (const GeometryError& e) {
    refuse(reader, class_name, e.reason());
  }
  return geometry;
}

}  // namespace

NurbsCurve checked(const ArchiveReader& reader, const char* class_name, NurbsCurve curve) {
  return validated(reader, class_name, std::move(curve));
}

NurbsSurface checked(const ArchiveReader& reader, const char* class_name, NurbsSurface surface) {
  return validated(reader, class_name, std::move(surface));
}

void read_control_points(ArchiveReader& reader, const char* class_name, int dimension, bool rational,
                         std::size_t count, std::vector<Eigen::Vector3d>& points, std::vector<double>& weights) {
  points.resize(count);
  weights.clear();
  if (rational) weights.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    double h[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < dimension; ++d) h[d] = reader.f64();
    if (!rational) {
      points[i] = Eigen::Vector3d(h[0], h[1], h[2]);
      continue;
    }
    const double w = reader.f64();
    if (!(w > 0.0))
      refuse(reader, class_name, "weight of control point " + std::to_string(i) + " is " + number_text(w, 17) +
                                     "; weights must be positive");
    // One reciprocal, three products: the Euclidean point openNURBS's GetCV reports, bit for bit.
    const double r = 1.0 / w;
    points[i] = Eigen::Vector3d(h[0] * r, h[1] * r, dimension == 3 ? h[2] * r : 0.0);
    weights[i] = w;
  }
}

NurbsCurve nested_curve(ArchiveReader& reader, const char* class_name, const std::string& what) {
  if (reader.open_chunks() >= kMaxOpenChunks)
    refuse(reader, class_name, what + " would nest deeper than " + std::to_string(kMaxOpenChunks) + " chunks");
  RhinoGeometry object = read_object(reader);
  if (auto* curve = std::get_if<NurbsCurve>(&object)) return std::move(*curve);
  std::string found = "a surface";
  if (const auto* unsupported = std::get_if<Unsupported>(&object))
    found = unsupported->class_name + ", which cadnurbs does not read";
  else if (std::holds_alternative<RhinoBrep>(object))
    found = "a Brep";
  else if (std::holds_alternative<TriangleMesh>(object))
    found = "a mesh";
  refuse(reader, class_name, what + " is " + found + ", not a curve");
}

std::pair<double, double> read_increasing_interval(ArchiveReader& reader, const char* class_name,
                                                   const std::string& what) {
  const double t0 = reader.f64(), t1 = reader.f64();
  if (!(t0 < t1))
    refuse(reader, class_name, what + " [" + number_text(t0, 17) + ", " + number_text(t1, 17) + "] does not increase");
  return {t0, t1};
}

std::vector<double> read_knots(ArchiveReader& reader, const char* class_name, const std::string& direction,
                               int order, int count) {
  const std::string knots = direction.empty() ? "knots" : direction + " knots";
  const std::size_t stored = read_count(reader, class_name, 8, knots);
  const std::int64_t expected = std::int64_t{order} + count - 2;
  if (static_cast<std::int64_t>(stored) != expected)
    refuse(reader, class_name,
           std::to_string(stored) + " " + knots + " stored, order " + std::to_string(order) + " and " +
               std::to_string(count) + " control points need " + std::to_string(expected));
  return with_end_knots(reader.doubles(stored));
}

std::vector<double> with_end_knots(const std::vector<double>& stored) {
  std::vector<double> knots;
  knots.reserve(stored.size() + 2);
  knots.push_back(stored.front());
  knots.insert(knots.end(), stored.begin(), stored.end());
  knots.push_back(stored.back());
  return knots;
}

}  // namespace cadnurbs::rhino
