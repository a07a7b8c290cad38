#include "formats/gltf/glb_writer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "formats/gltf/draco_primitive.hpp"
#include "formats/gltf/glb_container.hpp"
#include "formats/gltf/gltf_frame.hpp"
#include "formats/gltf/json_text.hpp"
#include "formats/gltf/meshopt_primitive.hpp"
#include "formats/gltf/node_primitives.hpp"
#include "formats/gltf/position_grid.hpp"

namespace cadnurbs {
namespace {

// glTF enumerations (glTF 2.0 spec, accessor.componentType and bufferView.target).
constexpr int kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

struct MeshoptView {
  std::size_t offset = 0, length = 0;  // of the compressed stream in buffer 0
  int stride = 0;
  long count = 0;
  const char* mode = "";
};

struct BufferView {
  int buffer = 0;
  std::size_t offset = 0, length = 0;
  int stride = 0;  // 0: not written
  int target = 0;  // 0: not written
  std::optional<MeshoptView> meshopt = std::nullopt;
};

struct Accessor {
  int view = -1;  // -1: no bufferView (the data is in a Draco stream)
  int component_type = kFloat;
  long count = 0;
  const char* type = "VEC3";
  std::vector<double> min = {}, max = {};
};

struct Primitive {
  int position = -1, indices = -1, material = -1;
  int draco_view = -1, draco_position_id = -1;
};

struct Node {
  std::string name;
  std::optional<Eigen::Matrix4d> matrix;
  std::optional<Eigen::Vector3d> translation;
  std::optional<double> scale;
  int mesh = -1;
  std::vector<int> children;
};

double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// Lays the scene out as glTF's arrays, then writes them as JSON.
class GltfDocument {
 public:
  GltfDocument(const Scene& scene, const GlbOptions& options) : options_(options), frame_(gltf_frame(scene.unit)) {
    collect(scene.root, Colour{}, display_name(scene.root));
    grid_ = position_grid(box_, options.compression == GlbCompression::none ? 16 : options.position_bits);
    add_node(scene.root);
  }

  std::string glb() const { return glb_container(json(), bin_); }

  GlbReport report(const LengthUnit& unit) const {
    GlbReport r = report_;
    r.nodes = static_cast<long>(nodes_.size());
    r.meshes = static_cast<long>(meshes_.size());
    r.materials = static_cast<long>(materials_.size());
    const double metres_per_unit = unit.millimetres / 1000.0;
    // The largest coordinate in metres, for float32 rounding.
    double largest = box_.isEmpty() ? 0 : std::max(box_.min().cwiseAbs().maxCoeff(), box_.max().cwiseAbs().maxCoeff());
    if (options_.compression != GlbCompression::none)
      largest = std::max(largest, grid_.origin.cwiseAbs().maxCoeff() + grid_.step * std::ldexp(1.0, grid_.bits));
    // float32 rounding: the input float, the decoder's float arithmetic (a few roundings).
    const double rounding = 4 * largest * std::ldexp(1.0, -24);
    const double step = options_.compression == GlbCompression::none ? 0 : grid_.step;
    r.position_step = step / metres_per_unit;
    r.max_position_error = std::sqrt(3.0) * (step / 2 + rounding) / metres_per_unit;
    return r;
  }

 private:
  // Pass 1: every node's primitives (in tree order) and box_, the box of all positions.
  void collect(const SceneNode& node, const Colour& inherited, const std::string& path) {
    const Colour colour = node.colour.value_or(inherited);
    node_geometry_.push_back(node_primitives(node, colour, frame_, path));
    report_.skipped_curves += node_geometry_.back().skipped_curves;
    for (const auto& primitive : node_geometry_.back().primitives)
      for (const auto& p : primitive.positions) box_.extend(p);
    for (const auto& child : node.children) collect(child, colour, path + "/" + display_name(child));
  }

  // Pass 2, same order as pass 1: nodes, meshes, data. Returns the node's index.
  int add_node(const SceneNode& node) {
    const NodePrimitives& geometry = node_geometry_[next_geometry_++];
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    nodes_[index].name = node.name;
    if (node.transform.matrix() != Eigen::Matrix4d::Identity()) {
      Eigen::Matrix4d frame = Eigen::Matrix4d::Identity();
      frame.topLeftCorner<3, 3>() = frame_;
      nodes_[index].matrix = frame * node.transform.matrix() * frame.inverse();
    }
    if (!geometry.primitives.empty()) {
      const int mesh = add_mesh(geometry, node.name);
      if (options_.compression == GlbCompression::meshopt) {
        // The grid coordinates' way back to metres; a child, so the node's own children are not scaled.
        Node holder;
        holder.translation = grid_.origin;
        holder.scale = grid_.step;
        holder.mesh = mesh;
        nodes_.push_back(holder);
        nodes_[index].children.push_back(static_cast<int>(nodes_.size()) - 1);
      } else {
        nodes_[index].mesh = mesh;
      }
    }
    for (const auto& child : node.children) {
      const int child_index = add_node(child);
      nodes_[index].children.push_back(child_index);
    }
    return index;
  }

  int material_of(const Colour& colour) {
    auto found = std::find(materials_.begin(), materials_.end(), colour);
    if (found != materials_.end()) return static_cast<int>(found - materials_.begin());
    materials_.push_back(colour);
    return static_cast<int>(materials_.size()) - 1;
  }

  // Appends bytes to buffer 0 at a 4-byte boundary; returns their offset.
  std::size_t append_bin(const void* data, std::size_t size) {
    bin_.append((4 - bin_.size() % 4) % 4, '\0');
    const std::size_t offset = bin_.size();
    bin_.append(static_cast<const char*>(data), size);
    return offset;
  }

  int add_view(BufferView view) {
    views_.push_back(view);
    return static_cast<int>(views_.size()) - 1;
  }

  int add_accessor(Accessor accessor) {
    accessors_.push_back(std::move(accessor));
    return static_cast<int>(accessors_.size()) - 1;
  }

  int add_mesh(const NodePrimitives& geometry, const std::string& name) {
    meshes_.emplace_back(name, std::vector<Primitive>{});
    const std::size_t mesh = meshes_.size() - 1;
    for (const auto& primitive : geometry.primitives) {
      Primitive p;
      p.material = material_of(primitive.colour);
      switch (options_.compression) {
        case GlbCompression::none: add_plain(primitive, p); break;
        case GlbCompression::draco: add_draco(primitive, p); break;
        case GlbCompression::meshopt: add_meshopt(primitive, p); break;
      }
      meshes_[mesh].second.push_back(p);
      ++report_.primitives;
    }
    return static_cast<int>(mesh);
  }

  void add_plain(const PrimitiveMesh& mesh, Primitive& p) {
    std::vector<float> positions;
    positions.reserve(3 * mesh.positions.size());
    Accessor position{.count = static_cast<long>(mesh.positions.size()),
                      .min = std::vector<double>(3, std::numeric_limits<double>::infinity()),
                      .max = std::vector<double>(3, -std::numeric_limits<double>::infinity())};
    for (const auto& point : mesh.positions)
      for (int axis = 0; axis < 3; ++axis) {
        const float v = static_cast<float>(point[axis]);
        positions.push_back(v);
        position.min[axis] = std::min<double>(position.min[axis], v);
        position.max[axis] = std::max<double>(position.max[axis], v);
      }
    const std::size_t bytes = positions.size() * sizeof(float);
    position.view = add_view({.offset = append_bin(positions.data(), bytes), .length = bytes, .target = kArrayBuffer});
    p.position = add_accessor(position);

    const bool small = mesh.positions.size() <= 65535;  // 65535 itself is reserved (primitive restart)
    std::string index_bytes;
    for (const auto i : mesh.indices)
      if (small) {
        const auto v = static_cast<std::uint16_t>(i);
        index_bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
      } else {
        index_bytes.append(reinterpret_cast<const char*>(&i), sizeof i);
      }
    const int view = add_view({.offset = append_bin(index_bytes.data(), index_bytes.size()),
                               .length = index_bytes.size(), .target = kElementArrayBuffer});
    p.indices = add_accessor({.view = view, .component_type = small ? kUnsignedShort : kUnsignedInt,
                              .count = static_cast<long>(mesh.indices.size()), .type = "SCALAR"});
    report_.vertices += static_cast<long>(mesh.positions.size());
    report_.triangles += static_cast<long>(mesh.indices.size() / 3);
  }

  void add_draco(const PrimitiveMesh& mesh, Primitive& p) {
    const DracoPrimitive draco = draco_primitive(mesh, grid_, options_.draco_speed);
    p.draco_view = add_view({.offset = append_bin(draco.bytes.data(), draco.bytes.size()), .length = draco.bytes.size()});
    p.draco_position_id = draco.position_id;
    // min / max of the decoded positions: the grid points of the extreme coordinates.
    Eigen::AlignedBox3d box;
    for (const auto& point : mesh.positions) box.extend(point);
    const Eigen::Vector3f low = grid_.position(grid_.quantised(box.min())).cast<float>();
    const Eigen::Vector3f high = grid_.position(grid_.quantised(box.max())).cast<float>();
    Accessor position{.count = draco.points, .min = {low.x(), low.y(), low.z()}, .max = {high.x(), high.y(), high.z()}};
    p.position = add_accessor(position);
    p.indices = add_accessor({.component_type = draco.points <= 65535 ? kUnsignedShort : kUnsignedInt,
                              .count = 3 * draco.faces, .type = "SCALAR"});
    report_.vertices += draco.points;
    report_.triangles += draco.faces;
  }

  void add_meshopt(const PrimitiveMesh& mesh, Primitive& p) {
    const MeshoptPrimitive encoded = meshopt_primitive(mesh, grid_);
    const auto fallback_view = [&](std::size_t length) {
      fallback_length_ += (4 - fallback_length_ % 4) % 4;
      const std::size_t offset = fallback_length_;
      fallback_length_ += length;
      return offset;
    };
    const std::size_t vertex_bytes = static_cast<std::size_t>(encoded.vertices) * MeshoptPrimitive::vertex_stride;
    BufferView vertices{.buffer = 1, .offset = fallback_view(vertex_bytes), .length = vertex_bytes,
                        .stride = MeshoptPrimitive::vertex_stride, .target = kArrayBuffer};
    vertices.meshopt = MeshoptView{append_bin(encoded.vertex_stream.data(), encoded.vertex_stream.size()),
                                   encoded.vertex_stream.size(), MeshoptPrimitive::vertex_stride, encoded.vertices,
                                   "ATTRIBUTES"};
    p.position = add_accessor({.view = add_view(vertices), .component_type = kUnsignedShort, .count = encoded.vertices,
                               .min = {double(encoded.min[0]), double(encoded.min[1]), double(encoded.min[2])},
                               .max = {double(encoded.max[0]), double(encoded.max[1]), double(encoded.max[2])}});

    const std::size_t index_bytes = static_cast<std::size_t>(encoded.indices) * encoded.index_size;
    BufferView indices{.buffer = 1, .offset = fallback_view(index_bytes), .length = index_bytes,
                       .target = kElementArrayBuffer};
    indices.meshopt = MeshoptView{append_bin(encoded.index_stream.data(), encoded.index_stream.size()),
                                  encoded.index_stream.size(), encoded.index_size, encoded.indices, "TRIANGLES"};
    p.indices = add_accessor({.view = add_view(indices),
                              .component_type = encoded.index_size == 2 ? kUnsignedShort : kUnsignedInt,
                              .count = encoded.indices, .type = "SCALAR"});
    report_.vertices += encoded.vertices;
    report_.triangles += encoded.indices / 3;
  }

  std::vector<std::string> extensions() const {
    if (meshes_.empty()) return {};
    switch (options_.compression) {
      case GlbCompression::draco: return {"KHR_draco_mesh_compression"};
      case GlbCompression::meshopt: return {"EXT_meshopt_compression", "KHR_mesh_quantization"};
      case GlbCompression::none: break;
    }
    return {};
  }

  std::string json() const {
    JsonText j;
    j.begin_object();
    j.key("asset").begin_object().key("version").string("2.0").key("generator").string("cadnurbs").end_object();
    if (const auto used = extensions(); !used.empty()) {
      // Nothing is left for a viewer without the extension, so each one used is also required.
      for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
        j.key(list).begin_array();
        for (const auto& name : used) j.string(name);
        j.end_array();
      }
    }
    j.key("scene").integer(0);
    j.key("scenes").begin_array().begin_object().key("nodes").begin_array().integer(0).end_array().end_object().end_array();
    write_nodes(j);
    write_meshes(j);
    write_materials(j);
    write_accessors(j);
    write_views(j);
    write_buffers(j);
    j.end_object();
    return j.text();
  }

  void write_nodes(JsonText& j) const {
    j.key("nodes").begin_array();
    for (const auto& node : nodes_) {
      j.begin_object();
      if (!node.name.empty()) j.key("name").string(node.name);
      if (node.matrix) {
        j.key("matrix").begin_array();
        for (int column = 0; column < 4; ++column)
          for (int row = 0; row < 4; ++row) j.number((*node.matrix)(row, column));
        j.end_array();
      }
      if (node.translation) {
        j.key("translation").begin_array();
        for (int axis = 0; axis < 3; ++axis) j.number((*node.translation)[axis]);
        j.end_array();
      }
      if (node.scale) j.key("scale").begin_array().number(*node.scale).number(*node.scale).number(*node.scale).end_array();
      if (node.mesh >= 0) j.key("mesh").integer(node.mesh);
      if (!node.children.empty()) {
        j.key("children").begin_array();
        for (const int child : node.children) j.integer(child);
        j.end_array();
      }
      j.end_object();
    }
    j.end_array();
  }

  void write_meshes(JsonText& j) const {
    if (meshes_.empty()) return;
    j.key("meshes").begin_array();
    for (const auto& [name, primitives] : meshes_) {
      j.begin_object();
      if (!name.empty()) j.key("name").string(name);
      j.key("primitives").begin_array();
      for (const auto& p : primitives) {
        j.begin_object();
        j.key("attributes").begin_object().key("POSITION").integer(p.position).end_object();
        j.key("indices").integer(p.indices);
        j.key("material").integer(p.material);
        if (p.draco_view >= 0) {
          j.key("extensions").begin_object().key("KHR_draco_mesh_compression").begin_object();
          j.key("bufferView").integer(p.draco_view);
          j.key("attributes").begin_object().key("POSITION").integer(p.draco_position_id).end_object();
          j.end_object().end_object();
        }
        j.end_object();
      }
      j.end_array();
      j.end_object();
    }
    j.end_array();
  }

  void write_materials(JsonText& j) const {
    if (materials_.empty()) return;
    j.key("materials").begin_array();
    for (const auto& colour : materials_) {
      j.begin_object();
      j.key("pbrMetallicRoughness").begin_object();
      j.key("baseColorFactor").begin_array();
      for (const double c : {colour.r, colour.g, colour.b}) j.number(srgb_to_linear(std::clamp(c, 0.0, 1.0)));
      j.number(1).end_array();
      j.key("metallicFactor").number(0).key("roughnessFactor").number(1);
      j.end_object();
      j.key("doubleSided").boolean(true);
      j.end_object();
    }
    j.end_array();
  }

  void write_accessors(JsonText& j) const {
    if (accessors_.empty()) return;
    j.key("accessors").begin_array();
    for (const auto& a : accessors_) {
      j.begin_object();
      if (a.view >= 0) j.key("bufferView").integer(a.view);
      j.key("componentType").integer(a.component_type);
      j.key("count").integer(a.count);
      j.key("type").string(a.type);
      for (const auto& [key, values] : {std::pair{"min", &a.min}, std::pair{"max", &a.max}}) {
        if (values->empty()) continue;
        j.key(key).begin_array();
        for (const double v : *values) j.number(v);
        j.end_array();
      }
      j.end_object();
    }
    j.end_array();
  }

  void write_views(JsonText& j) const {
    if (views_.empty()) return;
    j.key("bufferViews").begin_array();
    for (const auto& v : views_) {
      j.begin_object();
      j.key("buffer").integer(v.buffer);
      if (v.offset > 0) j.key("byteOffset").integer(static_cast<std::int64_t>(v.offset));
      j.key("byteLength").integer(static_cast<std::int64_t>(v.length));
      if (v.stride > 0) j.key("byteStride").integer(v.stride);
      if (v.target > 0) j.key("target").integer(v.target);
      if (v.meshopt) {
        j.key("extensions").begin_object().key("EXT_meshopt_compression").begin_object();
        j.key("buffer").integer(0);
        if (v.meshopt->offset > 0) j.key("byteOffset").integer(static_cast<std::int64_t>(v.meshopt->offset));
        j.key("byteLength").integer(static_cast<std::int64_t>(v.meshopt->length));
        j.key("byteStride").integer(v.meshopt->stride);
        j.key("count").integer(v.meshopt->count);
        j.key("mode").string(v.meshopt->mode);
        j.end_object().end_object();
      }
      j.end_object();
    }
    j.end_array();
  }

  void write_buffers(JsonText& j) const {
    if (bin_.empty()) return;
    j.key("buffers").begin_array();
    j.begin_object().key("byteLength").integer(static_cast<std::int64_t>(bin_.size())).end_object();
    if (fallback_length_ > 0) {
      j.begin_object().key("byteLength").integer(static_cast<std::int64_t>(fallback_length_));
      j.key("extensions").begin_object().key("EXT_meshopt_compression").begin_object();
      j.key("fallback").boolean(true).end_object().end_object();
      j.end_object();
    }
    j.end_array();
  }

  const GlbOptions& options_;
  Eigen::Matrix3d frame_;
  Eigen::AlignedBox3d box_;  // of every position (pass 1)
  PositionGrid grid_;
  std::vector<NodePrimitives> node_geometry_;  // per SceneNode, in tree order
  std::size_t next_geometry_ = 0;  // pass 2's place in node_geometry_
  std::vector<Node> nodes_;
  std::vector<std::pair<std::string, std::vector<Primitive>>> meshes_;
  std::vector<Colour> materials_;
  std::vector<Accessor> accessors_;
  std::vector<BufferView> views_;
  std::string bin_;
  std::size_t fallback_length_ = 0;
  GlbReport report_;
};

}  // namespace

std::string write_glb(const Scene& meshes_scene, const GlbOptions& options, GlbReport* report) {
  const int most_bits = options.compression == GlbCompression::meshopt ? 16 : 30;
  if (options.compression != GlbCompression::none && (options.position_bits < 1 || options.position_bits > most_bits))
    throw std::invalid_argument("glTF: position_bits " + std::to_string(options.position_bits) + " is outside 1.." +
                                std::to_string(most_bits) + " for " +
                                (options.compression == GlbCompression::draco ? "draco" : "meshopt"));
  if (options.draco_speed < 0 || options.draco_speed > 10)
    throw std::invalid_argument("glTF: draco_speed " + std::to_string(options.draco_speed) + " is outside 0..10");
  const GltfDocument document(meshes_scene, options);
  if (report) *report = document.report(meshes_scene.unit);
  return document.glb();
}

std::optional<GlbCompression> glb_compression_named(std::string_view name) {
  if (name == "none") return GlbCompression::none;
  if (name == "draco") return GlbCompression::draco;
  if (name == "meshopt") return GlbCompression::meshopt;
  return std::nullopt;
}

}  // namespace cadnurbs
