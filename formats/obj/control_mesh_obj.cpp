#include "formats/obj/control_mesh_obj.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

using Edge = std::array<int, 2>;

constexpr int kFormatVersion = 1;
constexpr std::string_view kHeaderStart = "# cadnurbs Loop control mesh, format ";

Edge undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Every edge of every triangle once, sorted, for binary searches.
std::vector<Edge> triangle_edges(const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Edge> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) edges.push_back(undirected(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

bool is_edge(const std::vector<Edge>& sorted_edges, const Edge& e) {
  return std::binary_search(sorted_edges.begin(), sorted_edges.end(), e);
}

// Refuses what parse_control_mesh_obj would refuse or change, so that every file written reads back
// to the same mesh. Indices in messages are the struct's (0-based).
void check_writable(const SubdivisionControlMesh& mesh) {
  const auto fail = [](const std::string& reason) { throw GeometryError("Loop control mesh", reason); };
  if (mesh.triangles.empty()) fail("no triangles");
  const int n = static_cast<int>(mesh.positions.size());
  for (int i = 0; i < n; ++i)
    if (!mesh.positions[i].allFinite()) fail("position " + std::to_string(i) + " is not finite");
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& c = mesh.triangles[t];
    for (int v : c)
      if (v < 0 || v >= n) fail("triangle " + std::to_string(t) + " has index " + std::to_string(v) + " out of range");
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) fail("triangle " + std::to_string(t) + " uses a vertex twice");
  }
  const std::vector<Edge> edges = triangle_edges(mesh.triangles);
  for (size_t k = 0; k < mesh.crease_edges.size(); ++k) {
    const Edge& e = mesh.crease_edges[k];
    const std::string which = "crease edge " + std::to_string(k) + " {" + std::to_string(e[0]) + ", " +
                              std::to_string(e[1]) + "}";
    if (e[0] >= e[1]) fail(which + " is not written with a < b");
    if (!is_edge(edges, e)) fail(which + " is not an edge of any triangle");
  }
  std::vector<Edge> creases = mesh.crease_edges;
  std::sort(creases.begin(), creases.end());
  if (std::adjacent_find(creases.begin(), creases.end()) != creases.end()) fail("a crease edge is listed twice");
  for (int v : mesh.corner_vertices)
    if (v < 0 || v >= n) fail("corner " + std::to_string(v) + " is out of range");
  std::vector<int> corners = mesh.corner_vertices;
  std::sort(corners.begin(), corners.end());
  if (std::adjacent_find(corners.begin(), corners.end()) != corners.end()) fail("a corner is listed twice");
}

// The crease edges as vertex chains in which each consecutive pair is one edge, every edge in exactly
// one chain. Walks start first at vertices of odd crease degree (each open walk ends at another one), then
// anywhere for the closed loops left, so a chain of creases becomes one polyline.
std::vector<std::vector<int>> crease_polylines(const std::vector<Edge>& creases, int vertex_count) {
  std::vector<std::vector<std::pair<int, size_t>>> around(static_cast<size_t>(vertex_count));  // (other end, edge)
  for (size_t e = 0; e < creases.size(); ++e) {
    around[creases[e][0]].push_back({creases[e][1], e});
    around[creases[e][1]].push_back({creases[e][0], e});
  }
  std::vector<char> used(creases.size(), 0);
  std::vector<size_t> first_unused(around.size(), 0);
  const auto unused_step = [&](int v) -> const std::pair<int, size_t>* {
    auto& k = first_unused[v];
    while (k < around[v].size() && used[around[v][k].second]) ++k;
    return k < around[v].size() ? &around[v][k] : nullptr;
  };
  std::vector<std::vector<int>> polylines;
  const auto walk_from = [&](int v) {
    std::vector<int> line{v};
    while (const auto* step = unused_step(v)) {
      used[step->second] = 1;
      v = step->first;
      line.push_back(v);
    }
    polylines.push_back(std::move(line));
  };
  for (int v = 0; v < vertex_count; ++v)
    if (around[v].size() % 2 == 1)
      while (unused_step(v)) walk_from(v);
  for (int v = 0; v < vertex_count; ++v)
    while (unused_step(v)) walk_from(v);
  return polylines;
}

void append_indices(std::string& out, char element, const std::vector<int>& zero_based) {
  out += element;
  for (int v : zero_based) out += ' ' + std::to_string(v + 1);
  out += '\n';
}

// The shortest text that reads back as the same double, always with a digit before the point (OBJ readers
// such as tinyobjloader refuse ".5") and with the sign of -0 kept, so positions round-trip bit for bit.
void append_coordinate(std::string& out, double x) {
  char text[32];
  out.append(text, std::to_chars(text, text + sizeof text, x).ptr);
}

constexpr std::array<std::string_view, 17> kSkippedElements = {
    "vn",  "vt",    "vp",     "o",        "g",        "s",          "mg",       "usemtl", "mtllib",
    "usemap", "maplib", "lod", "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj"};

// One pass over the lines. Positive indices may point forward, so their range, and whether each crease is an
// edge of a triangle, are checked once the whole file is read; messages still name the line.
class Parser {
 public:
  explicit Parser(const std::string& name) : name_(name) {}

  SubdivisionControlMesh parse(const std::string& text) {
    for (size_t start = 0; start < text.size();) {
      size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      ++line_;
      parse_line(std::string_view(text).substr(start, end - start));
      start = end + 1;
    }
    return finish();
  }

 private:
  struct ForwardIndex {
    long line;
    long long index;  // 1-based, as written
  };
  struct CreaseAt {
    Edge edge;
    long line;
  };

  void parse_line(std::string_view line) {
    if (line_ == 1 && line.starts_with(kHeaderStart)) check_version(line.substr(kHeaderStart.size()));
    line = line.substr(0, line.find('#'));
    words_.clear();
    for (size_t k = 0; k < line.size();) {
      const size_t first = line.find_first_not_of(" \t\r", k);
      if (first == std::string_view::npos) break;
      const size_t last = std::min(line.find_first_of(" \t\r", first), line.size());
      words_.push_back(line.substr(first, last - first));
      k = last;
    }
    if (words_.empty()) return;
    const std::string_view element = words_[0];
    const size_t count = words_.size() - 1;
    if (element == "v") {
      if (count < 3) fail("a vertex needs 3 coordinates, found " + std::to_string(count));
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k) p[k] = coordinate(words_[k + 1]);
      mesh_.positions.push_back(p);
    } else if (element == "f") {
      if (count != 3)
        fail("face with " + std::to_string(count) + " corners: " +
             (count > 3 ? "a Loop control mesh has triangles only (triangulate it first)" : "a face needs 3"));
      std::array<int, 3> t;
      for (int k = 0; k < 3; ++k) t[k] = vertex_index(words_[k + 1]);
      for (int k = 0; k < 3; ++k)
        if (t[k] == t[(k + 1) % 3]) fail("face uses vertex " + std::to_string(t[k] + 1) + " twice");
      mesh_.triangles.push_back(t);
    } else if (element == "l") {
      if (count < 2) fail("a line element needs at least 2 vertices, found " + std::to_string(count));
      int previous = vertex_index(words_[1]);
      for (size_t k = 2; k <= count; ++k) {
        const int v = vertex_index(words_[k]);
        creases_.push_back({undirected(previous, v), line_});
        previous = v;
      }
    } else if (element == "p") {
      if (count < 1) fail("a point element needs at least 1 vertex");
      for (size_t k = 1; k <= count; ++k) mesh_.corner_vertices.push_back(vertex_index(words_[k]));
    } else if (std::find(kSkippedElements.begin(), kSkippedElements.end(), element) == kSkippedElements.end()) {
      fail("element '" + std::string(element) + "' is not supported (a Loop control mesh has v, f, l and p)");
    }
  }

  void check_version(std::string_view rest) {
    const std::string_view written = rest.substr(0, rest.find_first_of(" \t\r,:;("));
    int version = 0;
    const auto [end, error] = std::from_chars(written.data(), written.data() + written.size(), version);
    if (error != std::errc() || end != written.data() + written.size() || version != kFormatVersion)
      fail("cadnurbs Loop control mesh format '" + std::string(written) + "' is not format " +
           std::to_string(kFormatVersion) + ", the one this reader knows");
  }

  double coordinate(std::string_view word) {
    const std::string_view digits = word.starts_with('+') ? word.substr(1) : word;
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const std::string which = "vertex " + std::to_string(mesh_.positions.size() + 1) + ": coordinate '" +
                              std::string(word) + "'";
    if (error == std::errc::result_out_of_range) fail(which + " is out of the range of double");
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty()) fail(which + " is not a number");
    if (!std::isfinite(value)) fail(which + " is not finite");
    return value;
  }

  // The vertex part of "a", "a/t", "a/t/n" or "a//n", resolved to a 0-based index.
  int vertex_index(std::string_view word) {
    const std::string_view written = word.substr(0, word.find('/'));
    long long index = 0;
    const auto [end, error] = std::from_chars(written.data(), written.data() + written.size(), index);
    if (error != std::errc() || end != written.data() + written.size() || written.empty())
      fail("vertex index '" + std::string(written) + "' is not an integer");
    if (index == 0) fail("vertex index 0 is not valid (OBJ counts vertices from 1)");
    const long long so_far = static_cast<long long>(mesh_.positions.size());
    if (index < 0) {
      if (so_far + index < 0)
        fail("vertex index " + std::to_string(index) + " is out of range (" + std::to_string(so_far) +
             " vertices before it)");
      return static_cast<int>(so_far + index);
    }
    if (index > INT_MAX) fail("vertex index " + std::to_string(index) + " is out of range");
    if (index > so_far) forward_.push_back({line_, index});
    return static_cast<int>(index - 1);
  }

  SubdivisionControlMesh finish() {
    if (mesh_.triangles.empty())
      throw FileError(name_ + ": no triangles (a Loop control mesh needs at least one face 'f a b c')");
    const long long vertex_count = static_cast<long long>(mesh_.positions.size());
    for (const ForwardIndex& f : forward_)
      if (f.index > vertex_count)
        fail_at(f.line, "vertex index " + std::to_string(f.index) + " is out of range (the file has " +
                            std::to_string(vertex_count) + " vertices)");
    const std::vector<Edge> edges = triangle_edges(mesh_.triangles);
    for (const CreaseAt& c : creases_) {
      if (!is_edge(edges, c.edge))
        fail_at(c.line, "crease edge " + std::to_string(c.edge[0] + 1) + "-" + std::to_string(c.edge[1] + 1) +
                            " is not an edge of any triangle");
      mesh_.crease_edges.push_back(c.edge);
    }
    auto& creases = mesh_.crease_edges;
    std::sort(creases.begin(), creases.end());
    creases.erase(std::unique(creases.begin(), creases.end()), creases.end());
    auto& corners = mesh_.corner_vertices;
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    return std::move(mesh_);
  }

  [[noreturn]] void fail(const std::string& problem) const { fail_at(line_, problem); }
  [[noreturn]] void fail_at(long line, const std::string& problem) const {
    throw FileError(name_ + ": line " + std::to_string(line) + ": " + problem);
  }

  const std::string& name_;
  long line_ = 0;
  std::vector<std::string_view> words_;
  SubdivisionControlMesh mesh_;
  std::vector<ForwardIndex> forward_;
  std::vector<CreaseAt> creases_;
};

}  // namespace

std::string format_control_mesh_obj(const SubdivisionControlMesh& mesh) {
  check_writable(mesh);
  std::string out(kHeaderStart);
  out += std::to_string(kFormatVersion) + " (l: crease edges, p: corner vertices; docs/control_mesh_obj.md)\n";
  for (const auto& p : mesh.positions) {
    out += 'v';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      append_coordinate(out, p[k]);
    }
    out += '\n';
  }
  for (const auto& t : mesh.triangles) append_indices(out, 'f', {t[0], t[1], t[2]});
  for (const auto& line : crease_polylines(mesh.crease_edges, static_cast<int>(mesh.positions.size())))
    append_indices(out, 'l', line);
  if (!mesh.corner_vertices.empty()) append_indices(out, 'p', mesh.corner_vertices);
  return out;
}

void write_control_mesh_obj(const std::string& path, const SubdivisionControlMesh& mesh) {
  write_file_atomically(path, format_control_mesh_obj(mesh));
}

SubdivisionControlMesh parse_control_mesh_obj(const std::string& text, const std::string& name_for_errors) {
  return Parser(name_for_errors).parse(text);
}

SubdivisionControlMesh read_control_mesh_obj(const std::string& path) { return parse_control_mesh_obj(read_file(path), path); }

}  // namespace cadnurbs
