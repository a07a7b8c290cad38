// The glTF writer against an independent reader (tinygltf) and decoder (Draco, meshoptimizer).
#include <draco/compression/decode.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>

#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/geometry_error.hpp"
#include "core/length_unit.hpp"
#include "formats/gltf/glb_writer.hpp"
#include "formats/gltf/meshopt_primitive.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

tinygltf::Model read_back(const std::string& glb) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = loader.LoadBinaryFromMemory(&model, &error, &warning,
                                              reinterpret_cast<const unsigned char*>(glb.data()),
                                              static_cast<unsigned int>(glb.size()));
  EXPECT_TRUE(ok) << error;
  return model;
}

// The accessor's elements as doubles (float, unsigned short or unsigned int components; tight or strided).
std::vector<double> values_of(const tinygltf::Model& model, int accessor_index) {
  const auto& accessor = model.accessors.at(accessor_index);
  const auto& view = model.bufferViews.at(accessor.bufferView);
  const auto& buffer = model.buffers.at(view.buffer);
  const int components = tinygltf::GetNumComponentsInType(accessor.type);
  const int size = tinygltf::GetComponentSizeInBytes(accessor.componentType);
  const std::size_t stride = view.byteStride ? view.byteStride : components * size;
  std::vector<double> out;
  for (std::size_t i = 0; i < accessor.count; ++i)
    for (int c = 0; c < components; ++c) {
      const unsigned char* p = buffer.data.data() + view.byteOffset + accessor.byteOffset + i * stride + c * size;
      if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        float v;
        std::memcpy(&v, p, 4);
        out.push_back(v);
      } else if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        out.push_back(v);
      } else {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        out.push_back(v);
      }
    }
  return out;
}

Shape triangle_shape(std::vector<Eigen::Vector3d> points, std::optional<Colour> colour) {
  TriangleMesh mesh;
  mesh.positions = std::move(points);
  mesh.triangles = {{0, 1, 2}};
  return Shape{.name = "face", .geometry = mesh, .colour = colour};
}

// In centimetres: "part" (moved by (10, 0, 2) cm and turned a quarter about +Z) holds a square of two
// triangles in one colour (sharing an edge) and a triangle in the node's colour; "empty" holds nothing.
Scene small_scene() {
  Scene scene;
  scene.unit = *length_unit_named("cm");
  scene.root.name = "assembly";
  SceneNode part;
  part.name = "part";
  part.colour = Colour{0.8, 0.8, 0.8};
  part.transform = Eigen::Translation3d(10, 0, 2) * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  const Colour violet{0.5, 0.2, 0.8};
  part.shapes.push_back(triangle_shape({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, violet));
  part.shapes.push_back(triangle_shape({{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}, violet));
  part.shapes.push_back(triangle_shape({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}}, std::nullopt));
  SceneNode empty;
  empty.name = "empty";
  scene.root.children = {part, empty};
  return scene;
}

TEST(GlbWriter, UncompressedReadsBackWithNamesColoursCountsMetresAndYUp) {
  GlbReport report;
  const tinygltf::Model model = read_back(write_glb(small_scene(), {}, &report));
  ASSERT_EQ(model.nodes.size(), 3u);
  EXPECT_EQ(model.nodes[0].name, "assembly");
  EXPECT_EQ(model.nodes[1].name, "part");
  EXPECT_EQ(model.nodes[2].name, "empty");
  EXPECT_EQ(model.nodes[0].children, (std::vector<int>{1, 2}));
  ASSERT_EQ(model.scenes.at(0).nodes, std::vector<int>{0});

  // The node's matrix in glTF's frame (column-major): the quarter turn about +Z is one about +Y
  // (x -> -z in glTF as x -> y in ours), the translation (10, 0, 2) cm is (0.1, 0.02, 0) m.
  const auto& m = model.nodes[1].matrix;
  ASSERT_EQ(m.size(), 16u);
  const std::vector<double> expected_matrix = {0, 0, -1, 0, /**/ 0, 1, 0, 0, /**/ 1, 0, 0, 0, /**/ 0.1, 0.02, 0, 1};
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(m[i], expected_matrix[i], 1e-15) << "matrix element " << i;

  // One mesh, one primitive per colour, the square's shared edge welded.
  ASSERT_EQ(model.nodes[1].mesh, 0);
  ASSERT_EQ(model.meshes.size(), 1u);
  const auto& primitives = model.meshes[0].primitives;
  ASSERT_EQ(primitives.size(), 2u);
  EXPECT_EQ(model.accessors[primitives[0].attributes.at("POSITION")].count, 4u);
  EXPECT_EQ(model.accessors[primitives[0].indices].count, 6u);
  EXPECT_EQ(model.accessors[primitives[1].attributes.at("POSITION")].count, 3u);
  EXPECT_EQ(model.accessors[primitives[1].indices].count, 3u);
  EXPECT_EQ(report.vertices, 7);
  EXPECT_EQ(report.triangles, 3);

  // Colours: sRGB 0.5, 0.2, 0.8 are linear 0.2140, 0.0331, 0.6038 (IEC 61966-2-1).
  ASSERT_EQ(model.materials.size(), 2u);
  const auto& violet = model.materials[primitives[0].material].pbrMetallicRoughness.baseColorFactor;
  const auto& grey = model.materials[primitives[1].material].pbrMetallicRoughness.baseColorFactor;
  const std::vector<double> expected_violet = {0.21404, 0.03310, 0.60383, 1}, expected_grey = {0.60383, 0.60383, 0.60383, 1};
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(violet[c], expected_violet[c], 1e-5);
    EXPECT_NEAR(grey[c], expected_grey[c], 1e-5);
  }

  // Positions: 1 cm = 0.01 m; (x, y, z) -> (x, z, -y). The square's corners, then the raised triangle.
  const std::vector<double> square = values_of(model, primitives[0].attributes.at("POSITION"));
  const std::vector<double> expected_square = {0, 0, 0, 0.01, 0, 0, 0.01, 0, -0.01, 0, 0, -0.01};
  ASSERT_EQ(square.size(), expected_square.size());
  for (std::size_t i = 0; i < square.size(); ++i) EXPECT_NEAR(square[i], expected_square[i], 1e-9) << i;
  const std::vector<double> raised = values_of(model, primitives[1].attributes.at("POSITION"));
  const std::vector<double> expected_raised = {0, 0.05, 0, 0.01, 0.05, 0, 0, 0.05, -0.01};
  ASSERT_EQ(raised.size(), expected_raised.size());
  for (std::size_t i = 0; i < raised.size(); ++i) EXPECT_NEAR(raised[i], expected_raised[i], 1e-9) << i;
  EXPECT_EQ(values_of(model, primitives[0].indices), (std::vector<double>{0, 1, 2, 0, 2, 3}));
}

TEST(GlbWriter, RefusesSurfacesAndBitsOutsideTheRange) {
  Scene scene = small_scene();
  scene.root.shapes.push_back(Shape{.name = "lid", .geometry = TrimmedSurface{}, .colour = std::nullopt});
  try {
    write_glb(scene, {});
    FAIL() << "a NURBS surface was written";
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "assembly/lid: glTF holds triangle meshes only: tessellate NURBS surfaces first");
  }
  EXPECT_THROW(write_glb(small_scene(), {.compression = GlbCompression::meshopt, .position_bits = 17}),
               std::invalid_argument);
  EXPECT_THROW(write_glb(small_scene(), {.compression = GlbCompression::draco, .position_bits = 0}),
               std::invalid_argument);
}

TEST(GlbWriter, MeshoptStreamsDecodeToTheGridPoints) {
  PrimitiveMesh mesh;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 2; ++j) mesh.positions.emplace_back(0.01 * i, 0.003 * j * i, std::sin(0.1 * i));
  for (std::uint32_t i = 0; i + 1 < 50; ++i) {
    const std::uint32_t a = 2 * i, b = 2 * i + 1, c = 2 * i + 2, d = 2 * i + 3;
    mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
  }
  Eigen::AlignedBox3d box;
  for (const auto& p : mesh.positions) box.extend(p);
  const PositionGrid grid = position_grid(box, 12);
  const MeshoptPrimitive encoded = meshopt_primitive(mesh, grid);
  std::vector<std::uint16_t> vertices(4 * encoded.vertices);
  ASSERT_EQ(meshopt_decodeVertexBuffer(vertices.data(), encoded.vertices, 8,
                                       reinterpret_cast<const unsigned char*>(encoded.vertex_stream.data()),
                                       encoded.vertex_stream.size()), 0);
  std::vector<std::uint16_t> indices(encoded.indices);
  ASSERT_EQ(meshopt_decodeIndexBuffer(indices.data(), encoded.indices, 2,
                                      reinterpret_cast<const unsigned char*>(encoded.index_stream.data()),
                                      encoded.index_stream.size()), 0);
  ASSERT_EQ(encoded.indices, static_cast<long>(mesh.indices.size()));
  // Every decoded triangle is one of the input's (corners within half a step, rotation allowed).
  const auto decoded = [&](std::uint16_t v) { return grid.position({vertices[4 * v], vertices[4 * v + 1], vertices[4 * v + 2]}); };
  double worst = 0;
  for (std::size_t t = 0; t < indices.size(); t += 3) {
    double best = INFINITY;
    for (std::size_t u = 0; u < mesh.indices.size(); u += 3)
      for (int r = 0; r < 3; ++r) {
        double d = 0;
        for (int k = 0; k < 3; ++k)
          d = std::max(d, (decoded(indices[t + k]) - mesh.positions[mesh.indices[u + (k + r) % 3]]).cwiseAbs().maxCoeff());
        best = std::min(best, d);
      }
    worst = std::max(worst, best);
  }
  EXPECT_LE(worst, grid.step / 2 * (1 + 1e-9));
}

// capping-90 at 0.1 mm, the sample the browser test shows.
const Scene& capping_meshes() {
  static const Scene meshes =
      tessellate_to_deviation(read_vrml(CADNURBS_SOURCE_DIR "/samples/capping-90.x3dv"), 0.1);
  return meshes;
}

TEST(GlbWriter, CompressedCappingIsSmallerAndDracoDecodesToTheSameMesh) {
  GlbReport plain_report, draco_report, meshopt_report;
  const std::string plain = write_glb(capping_meshes(), {}, &plain_report);
  const std::string draco = write_glb(capping_meshes(), {.compression = GlbCompression::draco}, &draco_report);
  const std::string meshopt = write_glb(capping_meshes(), {.compression = GlbCompression::meshopt}, &meshopt_report);
  RecordProperty("bytes_none", std::to_string(plain.size()));
  RecordProperty("bytes_draco", std::to_string(draco.size()));
  RecordProperty("bytes_meshopt", std::to_string(meshopt.size()));
  std::printf("capping-90 at 0.1 mm: none %zu, draco %zu, meshopt %zu bytes; %ld triangles; grid step %.4g mm\n",
              plain.size(), draco.size(), meshopt.size(), plain_report.triangles, draco_report.position_step);
  EXPECT_LT(draco.size(), plain.size() / 3);
  EXPECT_LT(meshopt.size(), plain.size() / 2);
  EXPECT_EQ(meshopt_report.triangles, plain_report.triangles);
  EXPECT_LE(draco_report.max_position_error, 0.1);

  // tinygltf 2.7 refuses the Draco file (it wants a bufferView on every indices accessor, which
  // KHR_draco_mesh_compression leaves out), so the Draco streams are found in the BIN chunk by their
  // "DRACO" magic, decoded by Draco's decoder, and compared with the uncompressed file as tinygltf reads it.
  EXPECT_NE(draco.find("\"extensionsRequired\":[\"KHR_draco_mesh_compression\"]"), std::string::npos);
  const auto uint32_at = [&](std::size_t offset) {
    std::uint32_t v;
    std::memcpy(&v, draco.data() + offset, 4);
    return v;
  };
  ASSERT_EQ(draco.substr(0, 4), "glTF");
  ASSERT_EQ(uint32_at(8), draco.size());
  const std::size_t bin_start = 20 + uint32_at(12) + 8;
  ASSERT_EQ(draco.substr(bin_start - 4, 4), std::string("BIN\0", 4));
  const std::string bin = draco.substr(bin_start, uint32_at(bin_start - 8));
  std::vector<std::size_t> streams;
  for (std::size_t at = bin.find("DRACO"); at != std::string::npos; at = bin.find("DRACO", at + 1)) streams.push_back(at);
  EXPECT_EQ(static_cast<long>(streams.size()), draco_report.primitives);
  streams.push_back(bin.size());

  const auto area = [](const std::vector<Eigen::Vector3d>& p, const std::vector<std::uint32_t>& index) {
    double sum = 0;
    for (std::size_t t = 0; t < index.size(); t += 3)
      sum += 0.5 * (p[index[t + 1]] - p[index[t]]).cross(p[index[t + 2]] - p[index[t]]).norm();
    return sum;
  };
  double draco_area = 0;
  long draco_points = 0, draco_triangles = 0;
  for (std::size_t s = 0; s + 1 < streams.size(); ++s) {
    draco::DecoderBuffer buffer;
    buffer.Init(bin.data() + streams[s], streams[s + 1] - streams[s]);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    ASSERT_TRUE(decoded.ok()) << decoded.status().error_msg();
    const auto& mesh = *decoded.value();
    const auto* position = mesh.GetNamedAttribute(draco::GeometryAttribute::POSITION);
    ASSERT_NE(position, nullptr);
    std::vector<Eigen::Vector3d> points(mesh.num_points());
    for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
      float v[3];
      position->GetMappedValue(i, v);
      points[i.value()] = Eigen::Vector3d(v[0], v[1], v[2]);
    }
    std::vector<std::uint32_t> index;
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
      for (int c = 0; c < 3; ++c) index.push_back(mesh.face(f)[c].value());
    draco_area += area(points, index);
    draco_points += mesh.num_points();
    draco_triangles += mesh.num_faces();
  }
  EXPECT_EQ(draco_points, draco_report.vertices);
  EXPECT_EQ(draco_triangles, draco_report.triangles);
  EXPECT_EQ(draco_triangles, plain_report.triangles);

  const tinygltf::Model plain_model = read_back(plain);
  double plain_area = 0;
  for (const auto& mesh : plain_model.meshes)
    for (const auto& primitive : mesh.primitives) {
      const std::vector<double> xyz = values_of(plain_model, primitive.attributes.at("POSITION"));
      std::vector<Eigen::Vector3d> points;
      for (std::size_t i = 0; i < xyz.size(); i += 3) points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
      const std::vector<double> index = values_of(plain_model, primitive.indices);
      plain_area += area(points, std::vector<std::uint32_t>(index.begin(), index.end()));
    }
  EXPECT_NEAR(draco_area, plain_area, 1e-3 * plain_area);
}

}  // namespace
}  // namespace cadnurbs
