#include "formats/stl/stl_writer.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"
#include "formats/stl/facet_normal.hpp"

namespace cadnurbs {
namespace {

using Vector3f = std::array<float, 3>;

// One triangle as STL stores it: float32 normal and corners.
struct Facet {
  Vector3f normal;
  std::array<Vector3f, 3> corners;
};

// The float32 facets of the mesh; refuses a coordinate that does not fit float32.
std::vector<Facet> float_facets(const TriangleMesh& mesh, const std::string& entity) {
  std::vector<Facet> facets;
  facets.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Facet facet;
    std::array<Eigen::Vector3d, 3> rounded;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& p = mesh.positions[mesh.triangles[t][k]];
      for (int i = 0; i < 3; ++i) {
        facet.corners[k][i] = static_cast<float>(p[i]);
        if (!std::isfinite(facet.corners[k][i]))
          throw GeometryError(entity, "triangle " + std::to_string(t) + " corner " + std::to_string(k) +
                                          " has coordinate " + std::to_string(p[i]) + ", beyond float32 (STL)");
        rounded[k][i] = facet.corners[k][i];
      }
    }
    const Eigen::Vector3d n = facet_normal(rounded[0], rounded[1], rounded[2]);
    facet.normal = {static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())};
    facets.push_back(facet);
  }
  return facets;
}

void put_u32le(std::string& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) out += static_cast<char>((value >> shift) & 0xffu);
}

void put_vec3f(std::string& out, const Vector3f& v) {
  for (float x : v) put_u32le(out, std::bit_cast<std::uint32_t>(x));
}

std::string format_binary(const std::vector<Facet>& facets, const std::string& solid_name, const std::string& entity) {
  if (facets.size() > std::numeric_limits<std::uint32_t>::max())
    throw GeometryError(entity, std::to_string(facets.size()) + " triangles, binary STL holds at most 2^32 - 1");
  std::string out = ("cadnurbs " + solid_name).substr(0, 80);
  out.resize(80, ' ');
  out.reserve(84 + 50 * facets.size());
  put_u32le(out, static_cast<std::uint32_t>(facets.size()));
  for (const Facet& facet : facets) {
    put_vec3f(out, facet.normal);
    for (const Vector3f& corner : facet.corners) put_vec3f(out, corner);
    out += std::string(2, '\0');  // attribute byte count
  }
  return out;
}

// " x y z", each value as printf "%.9g" would print it (9 significant digits give the float32 back),
// independent of the C locale.
void put_numbers(std::string& out, const Vector3f& v) {
  for (float x : v) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, 9);
    out += ' ';
    out.append(buffer, result.ptr);
  }
}

std::string format_ascii(const std::vector<Facet>& facets, const std::string& solid_name) {
  std::string name = solid_name;
  for (char& c : name)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  const std::string suffix = name.empty() ? "" : " " + name;
  std::string out = "solid" + suffix + "\n";
  out.reserve(260 * facets.size() + 2 * out.size());
  for (const Facet& facet : facets) {
    out += "  facet normal";
    put_numbers(out, facet.normal);
    out += "\n    outer loop\n";
    for (const Vector3f& corner : facet.corners) {
      out += "      vertex";
      put_numbers(out, corner);
      out += '\n';
    }
    out += "    endloop\n  endfacet\n";
  }
  out += "endsolid" + suffix + "\n";
  return out;
}

}  // namespace

std::string format_stl(const TriangleMesh& mesh, StlEncoding encoding, const std::string& solid_name) {
  const std::string entity = solid_name.empty() ? "STL mesh" : solid_name;
  validate(mesh, entity);
  const std::vector<Facet> facets = float_facets(mesh, entity);
  return encoding == StlEncoding::binary ? format_binary(facets, solid_name, entity) : format_ascii(facets, solid_name);
}

void write_stl(const std::string& path, const TriangleMesh& mesh, StlEncoding encoding, const std::string& solid_name) {
  write_file_atomically(path, format_stl(mesh, encoding, solid_name));
}

}  // namespace cadnurbs
