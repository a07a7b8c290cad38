#include "formats/stl/stl_reader.hpp"

#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "formats/common/file_io.hpp"
#include "formats/stl/facet_normal.hpp"

namespace cadnurbs {
namespace {

constexpr std::uint64_t kHeaderBytes = 84;  // 80-byte header + uint32 triangle count
constexpr std::uint64_t kFacetBytes = 50;   // normal, 3 vertices (12 float32), uint16 attribute

using Corners = std::array<Eigen::Vector3d, 3>;

// A facet normal the file really supplies: finite and not the zero vector.
bool is_supplied(const Eigen::Vector3d& normal) { return normal.allFinite() && (normal.array() != 0.0).any(); }

// Collects facets in file order and applies the corner-normal rule of parse_stl.
class MeshBuilder {
 public:
  void reserve(std::size_t facets) {
    mesh_.positions.reserve(3 * facets);
    mesh_.triangles.reserve(facets);
    normals_.reserve(facets);
  }

  void add(const Eigen::Vector3d& normal, const Corners& corners) {
    const int first = static_cast<int>(mesh_.positions.size());
    mesh_.positions.insert(mesh_.positions.end(), corners.begin(), corners.end());
    mesh_.triangles.push_back({first, first + 1, first + 2});
    normals_.push_back(normal);
    if (is_supplied(normal)) any_normal_ = true;
  }

  TriangleMesh finish() && {
    if (!any_normal_) return std::move(mesh_);
    mesh_.corner_normals.reserve(3 * normals_.size());
    for (std::size_t t = 0; t < normals_.size(); ++t) {
      const Eigen::Vector3d& n = normals_[t];
      const Eigen::Vector3d unit = is_supplied(n)
                                       ? Eigen::Vector3d(n.normalized())
                                       : facet_normal(mesh_.positions[3 * t], mesh_.positions[3 * t + 1],
                                                      mesh_.positions[3 * t + 2]);
      mesh_.corner_normals.insert(mesh_.corner_normals.end(), 3, unit);
    }
    return std::move(mesh_);
  }

 private:
  TriangleMesh mesh_;
  std::vector<Eigen::Vector3d> normals_;
  bool any_normal_ = false;
};

// ---------------------------------------------------------------------------------------------
// Binary

std::uint32_t read_u32le(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 | std::uint32_t{b[3]} << 24;
}

Eigen::Vector3d read_vec3(const char* p) {
  return {std::bit_cast<float>(read_u32le(p)), std::bit_cast<float>(read_u32le(p + 4)),
          std::bit_cast<float>(read_u32le(p + 8))};
}

std::uint64_t binary_size(std::uint32_t count) { return kHeaderBytes + kFacetBytes * count; }

// Parses a binary STL whose size has been checked to be binary_size(count).
TriangleMesh parse_binary(const std::string& bytes, const std::string& name) {
  const std::uint32_t count = read_u32le(bytes.data() + 80);
  MeshBuilder builder;
  builder.reserve(count);
  for (std::uint64_t t = 0; t < count; ++t) {
    const char* facet = bytes.data() + kHeaderBytes + kFacetBytes * t;
    const Corners corners = {read_vec3(facet + 12), read_vec3(facet + 24), read_vec3(facet + 36)};
    for (int k = 0; k < 3; ++k)
      if (!corners[k].allFinite())
        throw FileError(name + ": byte " + std::to_string(facet + 12 + 12 * k - bytes.data()) + ": vertex " +
                        std::to_string(k + 1) + " of triangle " + std::to_string(t + 1) + " of " +
                        std::to_string(count) + " is not finite");
    builder.add(read_vec3(facet), corners);
  }
  return std::move(builder).finish();
}

// The error for a file that is neither ASCII STL nor a binary STL of the right size.
FileError binary_size_error(const std::string& bytes, const std::string& name) {
  const std::uint64_t size = bytes.size();
  if (size < kHeaderBytes)
    return FileError(name + ": not ASCII STL (no 'solid' at the start) and too short for binary STL (" +
                     std::to_string(size) + " bytes, the header alone is 84)");
  const std::uint32_t count = read_u32le(bytes.data() + 80);
  const std::uint64_t expected = binary_size(count);
  if (size < expected && (size - kHeaderBytes) % kFacetBytes == 0)  // whole triangles, fewer than the count
    return FileError(name + ": binary STL header counts " + std::to_string(count) + " triangles but the file holds " +
                     std::to_string((size - kHeaderBytes) / kFacetBytes) + " (the file should be " +
                     std::to_string(expected) + " bytes, it is " + std::to_string(size) + ")");
  if (size < expected) {
    const std::uint64_t triangle = (size - kHeaderBytes) / kFacetBytes + 1;
    return FileError(name + ": binary STL truncated at byte " + std::to_string(size) + ": triangle " +
                     std::to_string(triangle) + " of " + std::to_string(count) + " is incomplete (the file should be " +
                     std::to_string(expected) + " bytes)");
  }
  return FileError(name + ": binary STL has " + std::to_string(size - expected) + " bytes after triangle " +
                   std::to_string(count) + " of " + std::to_string(count) + " (the file should be " +
                   std::to_string(expected) + " bytes, it is " + std::to_string(size) + ")");
}

// ---------------------------------------------------------------------------------------------
// ASCII

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != b[i]) return false;
  return true;
}

// True when the text starts (after whitespace) with "solid" and its first kilobyte has no control
// bytes: a binary file whose header starts with "solid" has them in its count and floats.
bool looks_like_ascii(std::string_view text) {
  std::size_t start = 0;
  while (start < text.size() && is_space(text[start])) ++start;
  if (!iequals(text.substr(start, 5), "solid")) return false;
  for (char c : text.substr(0, 1024)) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && !is_space(c)) || u == 0x7f) return false;
  }
  return true;
}

// Whitespace-separated tokens with the line number of the last one returned.
class Tokens {
 public:
  explicit Tokens(std::string_view text) : text_(text) {}

  // The next token, or "" at the end of the text.
  std::string_view next() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }

  // Skips the rest of the current line (the name after "solid" or "endsolid").
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }

  int line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

// A token quoted for an error message, shortened and with non-printable bytes shown as '?'.
std::string quoted(std::string_view token) {
  if (token.empty()) return "end of file";
  std::string out = "'";
  for (char c : token.substr(0, 40)) out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
  return out + (token.size() > 40 ? "...'" : "'");
}

class AsciiParser {
 public:
  AsciiParser(std::string_view text, const std::string& name) : tokens_(text), name_(name) {}

  TriangleMesh parse() {
    std::string_view token = tokens_.next();
    while (true) {
      if (!iequals(token, "solid")) fail("expected 'solid', found " + quoted(token));
      tokens_.skip_line();
      while (true) {
        token = tokens_.next();
        if (iequals(token, "endsolid")) break;
        if (!iequals(token, "facet"))
          fail("expected 'facet' or 'endsolid' after " + (facets_ == 0 ? "'solid'" : "facet " + std::to_string(facets_)) +
               ", found " + quoted(token));
        parse_facet();
      }
      tokens_.skip_line();
      token = tokens_.next();
      if (token.empty()) return std::move(builder_).finish();
    }
  }

 private:
  // Parses one facet after its "facet" keyword.
  void parse_facet() {
    ++facets_;
    expect("normal");
    const Eigen::Vector3d normal = vec3("the normal");
    expect("outer");
    expect("loop");
    Corners corners;
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      corners[k] = vec3("vertex " + std::to_string(k + 1));
      if (!corners[k].allFinite())
        fail("vertex " + std::to_string(k + 1) + " of facet " + std::to_string(facets_) + " is not finite");
    }
    expect("endloop");
    expect("endfacet");
    builder_.add(normal, corners);
  }

  void expect(const char* keyword) {
    const std::string_view token = tokens_.next();
    if (!iequals(token, keyword))
      fail(std::string("expected '") + keyword + "' in facet " + std::to_string(facets_) + ", found " + quoted(token));
  }

  // Three numbers; refuses a token that is not a number or is out of the range of double.
  Eigen::Vector3d vec3(const std::string& what) {
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) {
      std::string_view token = tokens_.next();
      const std::string_view digits = token.starts_with('+') ? token.substr(1) : token;
      double value = 0.0;
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
      if (ec == std::errc::invalid_argument || end != digits.data() + digits.size() || digits.empty())
        fail("expected a number for " + what + " in facet " + std::to_string(facets_) + ", found " + quoted(token));
      if (ec == std::errc::result_out_of_range)
        fail("number out of range for " + what + " in facet " + std::to_string(facets_) + ": " + quoted(token));
      v[i] = value;
    }
    return v;
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw FileError(name_ + ": line " + std::to_string(tokens_.line()) + ": " + problem);
  }

  Tokens tokens_;
  const std::string& name_;
  MeshBuilder builder_;
  int facets_ = 0;
};

}  // namespace

TriangleMesh parse_stl(const std::string& bytes, const std::string& name_for_errors) {
  if (bytes.empty()) throw FileError(name_for_errors + ": empty file (0 bytes), not an STL file");
  if (bytes.size() >= kHeaderBytes && bytes.size() == binary_size(read_u32le(bytes.data() + 80)))
    return parse_binary(bytes, name_for_errors);
  if (looks_like_ascii(bytes)) return AsciiParser(bytes, name_for_errors).parse();
  throw binary_size_error(bytes, name_for_errors);
}

TriangleMesh read_stl(const std::string& path) { return parse_stl(read_file(path), path); }

}  // namespace cadnurbs
