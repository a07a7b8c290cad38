#include "formats/gltf/draco_primitive.hpp"

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <cmath>
#include <stdexcept>

namespace cadnurbs {

DracoPrimitive draco_primitive(const PrimitiveMesh& mesh, const PositionGrid& grid, int speed) {
  draco::Mesh draco_mesh;
  const auto points = static_cast<draco::PointIndex::ValueType>(mesh.positions.size());
  draco_mesh.set_num_points(points);
  draco::GeometryAttribute position;
  position.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false, 3 * sizeof(float), 0);
  const int attribute = draco_mesh.AddAttribute(position, true, points);
  draco::PointAttribute* values = draco_mesh.attribute(attribute);
  for (draco::PointIndex::ValueType i = 0; i < points; ++i) {
    const Eigen::Vector3f p = mesh.positions[i].cast<float>();
    values->SetAttributeValue(draco::AttributeValueIndex(i), p.data());
  }
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    draco_mesh.AddFace({draco::PointIndex(mesh.indices[t]), draco::PointIndex(mesh.indices[t + 1]),
                        draco::PointIndex(mesh.indices[t + 2])});

  draco::Encoder encoder;
  encoder.SetSpeedOptions(speed, speed);
  encoder.SetTrackEncodedProperties(true);  // else num_encoded_points() stays 0
  const Eigen::Vector3f origin = grid.origin.cast<float>();
  const auto range = static_cast<float>(grid.step * (std::ldexp(1.0, grid.bits) - 1));
  encoder.SetAttributeExplicitQuantization(draco::GeometryAttribute::POSITION, grid.bits, 3, origin.data(), range);
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodeMeshToBuffer(draco_mesh, &buffer);
  if (!status.ok()) throw std::runtime_error(std::string("Draco: ") + status.error_msg());

  DracoPrimitive result;
  result.bytes.assign(buffer.data(), buffer.size());
  result.position_id = static_cast<int>(values->unique_id());
  result.points = static_cast<long>(encoder.num_encoded_points());
  result.faces = static_cast<long>(encoder.num_encoded_faces());
  return result;
}

}  // namespace cadnurbs
