#include "formats/nurss/nurss_text.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

constexpr std::string_view kHeader = "#NURSS 1 quadratic";
// add_face checks its corners pairwise; a bound keeps a hostile file from costing hours.
constexpr long kMostCornersPerFace = 4096;

void append_line(std::string& out, const std::vector<double>& values, const NumberPrecision& precision) {
  for (size_t k = 0; k < values.size(); ++k) {
    if (k) out += ' ';
    append_number(out, values[k], precision);
  }
  out += '\n';
}

bool side_has_face(const NurssMesh& mesh, NurssVertexId a, NurssVertexId b) {
  return mesh.face_with_side(a, b).has_value();
}

// The text cut into lines (a last empty line after the final newline dropped, "\r" before "\n" too),
// read one at a time with their 1-based numbers for messages.
class LineReader {
 public:
  LineReader(const std::string& text, std::string name) : name_(std::move(name)) {
    size_t start = 0;
    while (start < text.size()) {
      size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      std::string_view line(text.data() + start, end - start);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      lines_.push_back(line);
      start = end + 1;
    }
  }
  long left() const { return static_cast<long>(lines_.size()) - next_; }
  long number() const { return next_; }  // of the line last taken (1-based)
  [[noreturn]] void fail(const std::string& reason) const { fail_at(std::max<long>(next_, 1), reason); }
  [[noreturn]] void fail_at(long line, const std::string& reason) const {
    throw FileError(name_ + ": line " + std::to_string(line) + ": " + reason);
  }
  // The next line split at spaces and tabs; `what` names it in the message when there is none.
  std::vector<std::string_view> take(const std::string& what) {
    if (left() <= 0) {
      ++next_;
      fail("the file ends where " + what + " should be");
    }
    const std::string_view line = lines_[next_++];
    std::vector<std::string_view> words;
    size_t k = 0;
    while (k < line.size()) {
      while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) ++k;
      const size_t start = k;
      while (k < line.size() && line[k] != ' ' && line[k] != '\t') ++k;
      if (k > start) words.push_back(line.substr(start, k - start));
    }
    return words;
  }
  std::string_view raw_next() const { return left() > 0 ? lines_[next_] : std::string_view(); }
  void skip() { ++next_; }

  double number_in(std::string_view word, const std::string& what) const {
    double value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size())
      fail(what + " '" + std::string(word) + "' is not a number");
    if (!std::isfinite(value)) fail(what + " " + std::string(word) + " is not finite");
    return value;
  }
  double interval_in(std::string_view word) const {
    const double d = number_in(word, "knot interval");
    if (d < 0) fail("knot interval " + std::string(word) + " is negative");
    return d;
  }
  long count_in(std::string_view word, const std::string& what) const {
    long value = -1;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size() || value < 0)
      fail(what + " '" + std::string(word) + "' is not a whole number >= 0");
    return value;
  }
  // "<keyword> <count>", one line per item to follow: the count may not exceed the lines left (checked
  // before anything is allocated for it).
  long section(const std::string& keyword) {
    const auto words = take("the '" + keyword + "' line");
    if (words.size() != 2 || words[0] != keyword) fail("expected '" + keyword + " <count>'");
    const long n = count_in(words[1], keyword + " count");
    if (n > left())
      fail(keyword + " count " + std::to_string(n) + " exceeds the " + std::to_string(left()) + " lines left");
    return n;
  }

 private:
  std::string name_;
  std::vector<std::string_view> lines_;
  long next_ = 0;
};

}  // namespace

std::string write_nurss_text(const NurssMesh& mesh, const LengthUnit& unit, const NumberPrecision& precision) {
  validate(mesh, "NURSS mesh");
  if (unit.name.empty() || unit.name.find_first_of(" \t\r\n") != std::string::npos)
    throw std::invalid_argument("NURSS text: unit name '" + unit.name + "' is empty or has white space");
  std::string out(kHeader);
  out += "\nunit " + unit.name + ' ';
  append_number(out, unit.millimetres, {});
  out += "\nvertices " + std::to_string(mesh.vertex_count()) + '\n';
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const Eigen::Vector3d& p = mesh.position(NurssVertexId(v));
    append_line(out, {p.x(), p.y(), p.z(), mesh.weight(NurssVertexId(v))}, precision);
  }
  out += "faces " + std::to_string(mesh.face_count()) + '\n';
  for (int f = 0; f < mesh.face_count(); ++f) {
    const auto& c = mesh.corners(NurssFaceId(f));
    for (size_t k = 0; k < c.size(); ++k) {
      if (k) out += ' ';
      out += std::to_string(c[k].value);
    }
    out += '\n';
  }
  long labelled = 0;
  for (int f = 0; f < mesh.face_count(); ++f) labelled += mesh.label(NurssFaceId(f)) != 0;
  out += "labels " + std::to_string(labelled) + '\n';
  for (int f = 0; f < mesh.face_count(); ++f)
    if (mesh.label(NurssFaceId(f)) != 0) out += std::to_string(f) + ' ' + std::to_string(mesh.label(NurssFaceId(f))) + '\n';
  out += "intervals " + std::to_string(mesh.face_count()) + '\n';
  for (int f = 0; f < mesh.face_count(); ++f) {
    const auto& c = mesh.corners(NurssFaceId(f));
    std::vector<double> d;
    for (size_t k = 0; k < c.size(); ++k) d.push_back(mesh.interval(c[k], c[(k + 1) % c.size()]));
    append_line(out, d, precision);
  }
  // Sides of boundary edges that no face has: their start's interval is nowhere else.
  std::string open;
  long open_count = 0;
  for (int e = 0; e < mesh.edge_count(); ++e) {
    const NurssEdge& edge = mesh.edge(NurssEdgeId(e));
    for (int s = 0; s < 2; ++s) {
      const NurssVertexId a = edge.ends[s], b = edge.ends[1 - s];
      if (side_has_face(mesh, a, b)) continue;
      open += std::to_string(a.value) + ' ' + std::to_string(b.value) + ' ';
      append_number(open, edge.intervals[s], precision);
      open += '\n';
      ++open_count;
    }
  }
  out += "open-sides " + std::to_string(open_count) + '\n' + open;
  return out;
}

NurssMesh read_nurss_text(const std::string& text, const std::string& name, LengthUnit* unit) {
  LineReader in(text, name);
  if (in.left() == 0 || in.raw_next() != kHeader) {
    in.skip();
    in.fail("not a NURSS text file (the first line must be '" + std::string(kHeader) + "')");
  }
  in.skip();
  const auto unit_words = in.take("the 'unit' line");
  if (unit_words.size() != 3 || unit_words[0] != "unit") in.fail("expected 'unit <name> <millimetres>'");
  LengthUnit file_unit{std::string(unit_words[1]), in.number_in(unit_words[2], "unit length")};
  if (file_unit.millimetres <= 0) in.fail("unit length " + std::string(unit_words[2]) + " is not > 0");
  if (unit) *unit = file_unit;

  NurssMesh mesh;
  const long vertices = in.section("vertices");
  for (long v = 0; v < vertices; ++v) {
    const auto w = in.take("vertex " + std::to_string(v));
    if (w.size() != 4) in.fail("vertex " + std::to_string(v) + " has " + std::to_string(w.size()) + " values, not x y z w");
    const Eigen::Vector3d p(in.number_in(w[0], "x"), in.number_in(w[1], "y"), in.number_in(w[2], "z"));
    const double weight = in.number_in(w[3], "weight");
    if (weight <= 0) in.fail("vertex " + std::to_string(v) + " has weight " + std::string(w[3]) + "; weights must be > 0");
    mesh.add_vertex(p, weight);
  }
  const long faces = in.section("faces");
  std::vector<std::vector<NurssVertexId>> corner_lists(faces);
  std::vector<long> face_line(faces);
  for (long f = 0; f < faces; ++f) {
    const auto w = in.take("face " + std::to_string(f));
    face_line[f] = in.number();
    if (static_cast<long>(w.size()) > kMostCornersPerFace)
      in.fail("face " + std::to_string(f) + " has " + std::to_string(w.size()) + " corners; at most " +
              std::to_string(kMostCornersPerFace) + " are read");
    for (const auto word : w) {
      const long index = in.count_in(word, "corner index");
      if (index >= vertices)
        in.fail("corner index " + std::to_string(index) + " names no vertex (" + std::to_string(vertices) + " vertices)");
      corner_lists[f].emplace_back(static_cast<int>(index));
    }
  }
  const long labels = in.section("labels");
  std::vector<int> label_of(faces, 0);
  for (long k = 0; k < labels; ++k) {
    const auto w = in.take("label " + std::to_string(k));
    if (w.size() != 2) in.fail("expected '<face> <label>'");
    const long f = in.count_in(w[0], "face index");
    if (f >= faces) in.fail("face index " + std::to_string(f) + " names no face (" + std::to_string(faces) + " faces)");
    int label = 0;
    const auto [end, error] = std::from_chars(w[1].data(), w[1].data() + w[1].size(), label);
    if (error != std::errc() || end != w[1].data() + w[1].size())
      in.fail("label '" + std::string(w[1]) + "' is not a whole number");
    label_of[f] = label;
  }
  for (long f = 0; f < faces; ++f) {
    try {
      mesh.add_face(corner_lists[f], label_of[f]);
    } catch (const GeometryError& e) {
      in.fail_at(face_line[f], e.what());
    }
  }
  const long interval_lines = in.section("intervals");
  if (interval_lines != faces)
    in.fail("intervals count " + std::to_string(interval_lines) + " is not the face count " + std::to_string(faces));
  for (long f = 0; f < faces; ++f) {
    const auto& c = corner_lists[f];
    const auto w = in.take("the intervals of face " + std::to_string(f));
    if (w.size() != c.size())
      in.fail("face " + std::to_string(f) + " has " + std::to_string(c.size()) + " corners but " +
              std::to_string(w.size()) + " intervals");
    for (size_t k = 0; k < c.size(); ++k) {
      mesh.set_interval(c[k], c[(k + 1) % c.size()], in.interval_in(w[k]));
    }
  }
  const long open_sides = in.section("open-sides");
  for (long k = 0; k < open_sides; ++k) {
    const auto w = in.take("open side " + std::to_string(k));
    if (w.size() != 3) in.fail("expected '<from> <to> <interval>'");
    const long a = in.count_in(w[0], "vertex index"), b = in.count_in(w[1], "vertex index");
    if (a >= vertices || b >= vertices) in.fail("vertex index names no vertex");
    const NurssVertexId from(static_cast<int>(a)), to(static_cast<int>(b));
    if (!mesh.find_edge(from, to) || side_has_face(mesh, from, to) || !std::isnan(mesh.interval(from, to)))
      in.fail("side " + std::to_string(a) + "->" + std::to_string(b) + " is no open side, or is given twice");
    mesh.set_interval(from, to, in.interval_in(w[2]));
  }
  if (in.left() > 0) {
    in.skip();
    in.fail("unexpected text after the last section");
  }
  try {
    validate(mesh, "NURSS mesh");
  } catch (const GeometryError& e) {
    throw FileError(name + ": at the end: " + e.what());
  }
  return mesh;
}

}  // namespace cadnurbs
