#include "formats/stl/stl_reader.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string_view>
#include <vector>

#include "core/equal_points.hpp"
#include "core/worker_threads.hpp"
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
  explicit MeshBuilder(StlReadOptions options) : options_(options) {}

  void reserve(std::size_t facets) {
    if (options_.merge_equal_points)
      equal_.reserve(facets / 2 + 3);  // a closed surface of F triangles has about F / 2 vertices
    else
      mesh_.positions.reserve(3 * facets);
    mesh_.triangles.reserve(facets);
    if (options_.facet_normals) normals_.reserve(facets);
  }

  void add(const Eigen::Vector3d& normal, const Corners& corners) {
    if (options_.merge_equal_points) {
      const std::array<int, 3> numbers{number(corners[0]), number(corners[1]), number(corners[2])};
      mesh_.triangles.push_back(numbers);
      last_corners_ = corners;
      last_numbers_ = numbers;
    } else {
      const int first = static_cast<int>(mesh_.positions.size());
      mesh_.positions.insert(mesh_.positions.end(), corners.begin(), corners.end());
      mesh_.triangles.push_back({first, first + 1, first + 2});
    }
    if (!options_.facet_normals) return;
    normals_.push_back(normal);
    if (is_supplied(normal)) any_normal_ = true;
  }

  // Takes the builder of the facets that follow this one's; adds them as if this builder had read them.
  void append(MeshBuilder&& later) {
    std::vector<int> number;  // later's position numbers -> this builder's
    if (options_.merge_equal_points) {
      number.reserve(later.equal_.points().size());
      for (const Eigen::Vector3d& p : later.equal_.points()) number.push_back(equal_.add(p));
    } else {
      const int offset = static_cast<int>(mesh_.positions.size());
      for (std::size_t i = 0; i < later.mesh_.positions.size(); ++i) number.push_back(offset + static_cast<int>(i));
      mesh_.positions.insert(mesh_.positions.end(), later.mesh_.positions.begin(), later.mesh_.positions.end());
    }
    later.equal_ = EqualPoints();
    later.mesh_.positions = {};
    for (const auto& t : later.mesh_.triangles) mesh_.triangles.push_back({number[t[0]], number[t[1]], number[t[2]]});
    normals_.insert(normals_.end(), later.normals_.begin(), later.normals_.end());
    any_normal_ = any_normal_ || later.any_normal_;
    later = MeshBuilder(options_);
  }

  TriangleMesh finish() && {
    if (options_.merge_equal_points) mesh_.positions = std::move(equal_).take_points();
    if (!any_normal_) return std::move(mesh_);
    mesh_.corner_normals.reserve(3 * normals_.size());
    for (std::size_t t = 0; t < normals_.size(); ++t) {
      const Eigen::Vector3d& n = normals_[t];
      const Eigen::Vector3d unit = is_supplied(n)
                                       ? Eigen::Vector3d(n.normalized())
                                       : facet_normal(mesh_.positions[mesh_.triangles[t][0]],
                                                      mesh_.positions[mesh_.triangles[t][1]],
                                                      mesh_.positions[mesh_.triangles[t][2]]);
      mesh_.corner_normals.insert(mesh_.corner_normals.end(), 3, unit);
    }
    return std::move(mesh_);
  }

 private:
  // A corner's position number. Exporters write strips and fans, so a corner is more often than not one
  // of the previous facet's: those are found by comparing bits (EqualPoints' equality), without a probe
  // of the table.
  int number(const Eigen::Vector3d& p) {
    for (int k = 0; k < 3; ++k)
      if (last_numbers_[k] >= 0 && std::memcmp(last_corners_[k].data(), p.data(), sizeof(double) * 3) == 0)
        return last_numbers_[k];
    return equal_.add(p);
  }

  StlReadOptions options_;
  TriangleMesh mesh_;
  EqualPoints equal_;  // with merge_equal_points
  Corners last_corners_;                      // the previous facet's, with merge_equal_points
  std::array<int, 3> last_numbers_{-1, -1, -1};  // their numbers; -1 before the first facet
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

// Adds `count` facets of a binary STL file whose size has been checked to be binary_size(total), those
// from triangle `first` (0-based) on, held at `facets`.
void add_binary_facets(const char* facets, std::uint64_t first, std::uint64_t count, std::uint32_t total,
                       const std::string& name, MeshBuilder& builder) {
  for (std::uint64_t i = 0; i < count; ++i) {
    const char* facet = facets + kFacetBytes * i;
    const std::uint64_t t = first + i;
    const Corners corners = {read_vec3(facet + 12), read_vec3(facet + 24), read_vec3(facet + 36)};
    for (int k = 0; k < 3; ++k)
      if (!corners[k].allFinite())
        throw FileError(name + ": byte " + std::to_string(kHeaderBytes + kFacetBytes * t + 12 + 12 * k) + ": vertex " +
                        std::to_string(k + 1) + " of triangle " + std::to_string(t + 1) + " of " +
                        std::to_string(total) + " is not finite");
    builder.add(read_vec3(facet), corners);
  }
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
  AsciiParser(std::string_view text, const std::string& name, StlReadOptions options)
      : tokens_(text), name_(name), builder_(options) {}

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

  // Three numbers; refuses a token that is not a number or is out of the range of double ("inf" and "nan"
  // are read, and refused with the vertex named once the facet is complete).
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

TriangleMesh parse_stl(const std::string& bytes, const std::string& name_for_errors, StlReadOptions options) {
  if (bytes.empty()) throw FileError(name_for_errors + ": empty file (0 bytes), not an STL file");
  if (bytes.size() >= kHeaderBytes && bytes.size() == binary_size(read_u32le(bytes.data() + 80))) {
    const std::uint32_t count = read_u32le(bytes.data() + 80);
    MeshBuilder builder(options);
    builder.reserve(count);
    add_binary_facets(bytes.data() + kHeaderBytes, 0, count, count, name_for_errors, builder);
    return std::move(builder).finish();
  }
  if (looks_like_ascii(bytes)) return AsciiParser(bytes, name_for_errors, options).parse();
  throw binary_size_error(bytes, name_for_errors);
}

TriangleMesh read_stl(const std::string& path, StlReadOptions options) {
  // The size the file has: no read goes past it (a device or FIFO is refused before it is opened).
  const std::uint64_t size = regular_file_size(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path + ": cannot open (" + std::strerror(errno) + ")");
  // A binary file is read a block of facets at a time, not whole: its bytes would double the memory.
  std::string bytes(std::min<std::uint64_t>(size, kHeaderBytes), '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()))) throw FileError(path + ": read failed");
  if (size >= kHeaderBytes && size == binary_size(read_u32le(bytes.data() + 80))) {
    const std::uint32_t count = read_u32le(bytes.data() + 80);
    // A large file is read in parts at once, each by its own thread into its own builder, and the parts
    // appended in order: the same mesh as read in one go (MeshBuilder::append).
    constexpr std::uint32_t kFacetsPerThread = 1 << 16;
    const int workers = std::max(1, std::min(worker_threads(), static_cast<int>(count / kFacetsPerThread)));
    std::vector<MeshBuilder> parts(workers, MeshBuilder(options));
    on_workers(workers, [&](int w) {
      const auto [begin, end] = worker_range(count, w, workers);
      parts[w].reserve(w == 0 ? count : end - begin);  // the first part takes in the others
      std::ifstream part_in(path, std::ios::binary);
      if (!part_in.seekg(static_cast<std::streamoff>(kHeaderBytes + kFacetBytes * begin)))
        throw FileError(path + ": read failed");
      std::string block;
      constexpr std::uint64_t kBlock = 1 << 14;  // facets per read: 800 kB
      for (std::uint64_t first = begin; first < end; first += kBlock) {
        const std::uint64_t n = std::min<std::uint64_t>(kBlock, end - first);
        block.resize(kFacetBytes * n);
        if (!part_in.read(block.data(), static_cast<std::streamsize>(block.size())))
          throw FileError(path + ": read failed");
        add_binary_facets(block.data(), first, n, count, path, parts[w]);
      }
    });
    for (int w = 1; w < workers; ++w) parts[0].append(std::move(parts[w]));
    return std::move(parts[0]).finish();
  }
  bytes.resize(size);
  if (size > kHeaderBytes &&
      !in.read(bytes.data() + kHeaderBytes, static_cast<std::streamsize>(size - kHeaderBytes)))
    throw FileError(path + ": read failed");
  return parse_stl(bytes, path, options);
}

}  // namespace cadnurbs
