#include "formats/draco/draco_mesh_codec.hpp"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>
#include <cmath>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

const char* const kEntity = "Draco mesh";

void check_bits(int position_bits) {
  if (position_bits < 1 || position_bits > 30)
    throw GeometryError(kEntity, "position bits " + std::to_string(position_bits) + " outside 1..30");
}

}  // namespace

std::string encode_draco_mesh(const TriangleMesh& mesh, int position_bits, int speed) {
  validate(mesh, kEntity);
  check_bits(position_bits);
  if (speed < 0 || speed > 10) throw GeometryError(kEntity, "speed " + std::to_string(speed) + " outside 0..10");
  if (mesh.triangles.empty()) throw GeometryError(kEntity, "no triangles");

  // One point per vertex with its own attribute value (identity mapping): Draco sees exactly our
  // vertices, merged only where our indices merge them.
  draco::Mesh out;
  const auto n = static_cast<uint32_t>(mesh.positions.size());
  out.set_num_points(n);
  draco::GeometryAttribute position;
  position.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false, sizeof(float) * 3, 0);
  const int id = out.AddAttribute(position, true, n);
  draco::PointAttribute* attribute = out.attribute(id);
  for (uint32_t i = 0; i < n; ++i) {
    const float p[3] = {static_cast<float>(mesh.positions[i].x()), static_cast<float>(mesh.positions[i].y()),
                        static_cast<float>(mesh.positions[i].z())};
    attribute->SetAttributeValue(draco::AttributeValueIndex(i), p);
  }
  for (const auto& t : mesh.triangles)
    out.AddFace({draco::PointIndex(static_cast<uint32_t>(t[0])), draco::PointIndex(static_cast<uint32_t>(t[1])),
                 draco::PointIndex(static_cast<uint32_t>(t[2]))});

  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, position_bits);
  encoder.SetSpeedOptions(speed, speed);
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodeMeshToBuffer(out, &buffer);
  if (!status.ok()) throw GeometryError(kEntity, "Draco refuses it (" + status.error_msg_string() + ")");
  return std::string(buffer.data(), buffer.size());
}

TriangleMesh decode_draco_mesh(const std::string& bytes, const std::string& name) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) throw FileError(name + ": not a Draco mesh (" + decoded.status().error_msg_string() + ")");
  const std::unique_ptr<draco::Mesh> in = std::move(decoded).value();
  const draco::PointAttribute* position = in->GetNamedAttribute(draco::GeometryAttribute::POSITION);
  if (!position || position->num_components() != 3)
    throw FileError(name + ": Draco mesh without 3D positions");

  TriangleMesh mesh;
  const uint32_t n = in->num_points();
  mesh.positions.reserve(n);
  for (uint32_t i = 0; i < n; ++i) {
    float p[3];
    if (!position->ConvertValue<float, 3>(position->mapped_index(draco::PointIndex(i)), p))
      throw FileError(name + ": Draco position " + std::to_string(i) + " cannot be read");
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw FileError(name + ": Draco position " + std::to_string(i) + " is not finite");
    mesh.positions.emplace_back(p[0], p[1], p[2]);
  }
  mesh.triangles.reserve(in->num_faces());
  for (uint32_t f = 0; f < in->num_faces(); ++f) {
    const auto& face = in->face(draco::FaceIndex(f));
    std::array<int, 3> t{};
    for (int k = 0; k < 3; ++k) {
      if (face[k].value() >= n)
        throw FileError(name + ": Draco triangle " + std::to_string(f) + " refers to a missing vertex");
      t[k] = static_cast<int>(face[k].value());
    }
    mesh.triangles.push_back(t);
  }
  return mesh;
}

std::vector<Eigen::Vector3d> draco_quantised_positions(const TriangleMesh& mesh, int position_bits) {
  check_bits(position_bits);
  std::vector<Eigen::Vector3d> out;
  if (mesh.positions.empty()) return out;
  // The same float operations, in the same order, as Draco's AttributeQuantizationTransform,
  // Quantizer and Dequantizer (1.5.5).
  std::vector<std::array<float, 3>> p(mesh.positions.size());
  for (size_t i = 0; i < p.size(); ++i)
    for (int c = 0; c < 3; ++c) p[i][c] = static_cast<float>(mesh.positions[i][c]);
  std::array<float, 3> lo = p[0], hi = p[0];
  for (const auto& q : p)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], q[c]);
      hi[c] = std::max(hi[c], q[c]);
    }
  float range = 0.f;
  for (int c = 0; c < 3; ++c) range = std::max(range, hi[c] - lo[c]);
  if (range == 0.f) range = 1.f;
  const auto max_quantised = static_cast<int32_t>((1u << static_cast<uint32_t>(position_bits)) - 1);
  const float inverse_step = static_cast<float>(max_quantised) / range;
  const float step = range / static_cast<float>(max_quantised);
  out.reserve(p.size());
  for (const auto& q : p) {
    Eigen::Vector3d decoded;
    for (int c = 0; c < 3; ++c) {
      float value = q[c] - lo[c];
      value *= inverse_step;
      const auto integer = static_cast<int32_t>(std::floor(value + 0.5f));
      const float offset = static_cast<float>(integer) * step;
      decoded[c] = offset + lo[c];
    }
    out.push_back(decoded);
  }
  return out;
}

}  // namespace cadnurbs
