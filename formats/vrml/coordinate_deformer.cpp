#include "formats/vrml/coordinate_deformer.hpp"

#include <stdexcept>

#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

const char* const kDirections[3] = {"u", "v", "w"};

int integer_field(const Node& node, const std::string& name, int fallback) {
  const int* value = node.get<int>(name);
  return value ? *value : fallback;
}

// The `order` basis values of direction d at t, into n; returns the first control index they weigh.
int basis(const NurbsVolume& volume, int d, double t, double* n) {
  const int order = volume.orders[d];
  const int span = find_knot_span(volume.knots[d], order, volume.counts[d], t);
  double left[kMaxStackOrder], right[kMaxStackOrder];
  basis_function_values(volume.knots[d].data(), order, span, t, n, left, right);
  return span - order + 1;
}

}  // namespace

NurbsVolume coordinate_deformer_volume(const Node& deformer, bool homogeneous) {
  NurbsVolume volume;
  for (int d = 0; d < 3; ++d) {
    const std::string dir = kDirections[d];
    volume.counts[d] = integer_field(deformer, dir + "Dimension", 0);
    volume.orders[d] = integer_field(deformer, dir + "Order", 2);
    if (volume.orders[d] < 2 || volume.orders[d] > kMaxStackOrder)
      throw std::invalid_argument(dir + "Order " + std::to_string(volume.orders[d]) + " is not in 2.." +
                                  std::to_string(kMaxStackOrder));
    if (const auto* knots = deformer.get<MFFloat>(dir + "Knot")) volume.knots[d] = knots->values;
    const std::string fault = knot_vector_fault(volume.knots[d], volume.orders[d], volume.counts[d]);
    if (!fault.empty()) throw std::invalid_argument(dir + "Knot: " + fault);
  }
  const auto* points = deformer.get<MFVec3f>("controlPoint");
  const size_t count = static_cast<size_t>(volume.counts[0]) * volume.counts[1] * volume.counts[2];
  if (!points || points->values.size() != count)
    throw std::invalid_argument("controlPoint holds " + std::to_string(points ? points->values.size() : 0) +
                                " points, not uDimension x vDimension x wDimension = " + std::to_string(count));
  volume.points = points->values;
  if (const auto* weights = deformer.get<MFFloat>("weight"); weights && !weights->values.empty()) {
    if (weights->values.size() != count)
      throw std::invalid_argument("weight holds " + std::to_string(weights->values.size()) + " values, not " +
                                  std::to_string(count));
    for (double w : weights->values)
      if (!(w > 0.0)) throw std::invalid_argument("a weight is not positive");
    volume.weights = weights->values;
    if (homogeneous)
      for (size_t i = 0; i < count; ++i) volume.points[i] /= volume.weights[i];
  }
  return volume;
}

Eigen::Vector3d volume_point(const NurbsVolume& volume, const Eigen::Vector3d& parameter) {
  double n[3][kMaxStackOrder];
  int first[3];
  for (int d = 0; d < 3; ++d) first[d] = basis(volume, d, parameter[d], n[d]);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double weight_sum = 0.0;
  const size_t nu = volume.counts[0], nuv = nu * volume.counts[1];
  for (int k = 0; k < volume.orders[2]; ++k)
    for (int j = 0; j < volume.orders[1]; ++j)
      for (int i = 0; i < volume.orders[0]; ++i) {
        const size_t index = (first[0] + i) + (first[1] + j) * nu + (first[2] + k) * nuv;
        const double w = n[0][i] * n[1][j] * n[2][k] * (volume.weights.empty() ? 1.0 : volume.weights[index]);
        sum += w * volume.points[index];
        weight_sum += w;
      }
  return volume.weights.empty() ? sum : Eigen::Vector3d(sum / weight_sum);
}

void deform_geometry(Geometry& geometry, const NurbsVolume& volume, const Eigen::Affine3d& to_deformer) {
  const Eigen::Affine3d to_local = to_deformer.inverse();
  auto move = [&](std::vector<Eigen::Vector3d>& points) {
    for (auto& p : points) p = to_local * volume_point(volume, to_deformer * p);
  };
  if (auto* polygons = std::get_if<PolygonMesh>(&geometry)) geometry = triangulated(*polygons);
  if (auto* surface = std::get_if<TrimmedSurface>(&geometry)) move(surface->surface.points);
  if (auto* curve = std::get_if<NurbsCurve>(&geometry)) move(curve->points);
  if (auto* mesh = std::get_if<TriangleMesh>(&geometry)) {
    move(mesh->positions);
    mesh->corner_normals.clear();
  }
}

}  // namespace cadnurbs
