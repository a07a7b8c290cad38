#include "formats/scene_stream/scene_stream.hpp"

#include <bit>
#include <cstdint>
#include <cstring>

#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

constexpr std::string_view kSceneMagic{"CNSCENE\0", 8};
constexpr std::string_view kTranslationMagic{"CNBREPT\0", 8};
constexpr uint32_t kVersion = 1;
constexpr int kMaxDepth = 10000;  // deeper trees would overflow the reader's stack; no CAD file has them

class Writer {
 public:
  std::string bytes;

  void u8(uint8_t x) { bytes.push_back(static_cast<char>(x)); }
  void u32(uint32_t x) { little_endian(x, 4); }
  void i32(int x) { little_endian(static_cast<uint32_t>(x), 4); }
  void u64(uint64_t x) { little_endian(x, 8); }
  void f64(double x) { little_endian(std::bit_cast<uint64_t>(x), 8); }
  void flag(bool x) { u8(x ? 1 : 0); }
  void text(const std::string& s) {
    u64(s.size());
    bytes += s;
  }
  void doubles(const std::vector<double>& xs) {
    u64(xs.size());
    for (double x : xs) f64(x);
  }
  void points(const std::vector<Eigen::Vector3d>& ps) {
    u64(ps.size());
    for (const auto& p : ps) for (int k = 0; k < 3; ++k) f64(p[k]);
  }
  void colour(const std::optional<Colour>& c) {
    flag(c.has_value());
    if (c) {
      f64(c->r);
      f64(c->g);
      f64(c->b);
    }
  }
  void unit(const LengthUnit& u) {
    text(u.name);
    f64(u.millimetres);
  }
  void curve(const NurbsCurve& c) {
    i32(c.dimension);
    i32(c.order);
    doubles(c.knots);
    points(c.points);
    doubles(c.weights);
  }
  void surface(const NurbsSurface& s) {
    i32(s.u_order);
    i32(s.v_order);
    i32(s.u_count);
    i32(s.v_count);
    doubles(s.u_knots);
    doubles(s.v_knots);
    points(s.points);
    doubles(s.weights);
  }
  void trimmed(const TrimmedSurface& t) {
    surface(t.surface);
    u64(t.loops.size());
    for (const auto& loop : t.loops) {
      u64(loop.segments.size());
      for (const auto& segment : loop.segments) {
        if (const auto* c = std::get_if<NurbsCurve>(&segment)) {
          u8(0);
          curve(*c);
        } else {
          const auto& polyline = std::get<Polyline2D>(segment);
          u8(1);
          u64(polyline.points.size());
          for (const auto& p : polyline.points) {
            f64(p.x());
            f64(p.y());
          }
        }
      }
      u64(loop.edges.size());
      for (const auto& e : loop.edges) {
        i32(e.edge);
        flag(e.reversed);
      }
    }
  }
  void geometry(const Geometry& g) {
    u8(static_cast<uint8_t>(g.index()));
    if (const auto* t = std::get_if<TrimmedSurface>(&g)) trimmed(*t);
    else if (const auto* c = std::get_if<NurbsCurve>(&g)) curve(*c);
    else if (const auto* m = std::get_if<TriangleMesh>(&g)) {
      points(m->positions);
      u64(m->triangles.size());
      for (const auto& t : m->triangles) for (int k : t) i32(k);
      points(m->corner_normals);
    } else {
      const auto& p = std::get<PolygonMesh>(g);
      points(p.positions);
      u64(p.polygons.size());
      for (const auto& polygon : p.polygons) {
        u64(polygon.size());
        for (int k : polygon) i32(k);
      }
    }
  }
  void node(const SceneNode& n) {
    text(n.name);
    text(n.source_entity);
    for (int k = 0; k < 16; ++k) f64(n.transform.matrix().data()[k]);
    colour(n.colour);
    u64(n.shapes.size());
    for (const auto& s : n.shapes) {
      text(s.name);
      geometry(s.geometry);
      colour(s.colour);
      text(s.source_type);
      text(s.source_entity);
    }
    u64(n.children.size());
    for (const auto& child : n.children) node(child);
  }
  void scene(const Scene& s) {
    node(s.root);
    unit(s.unit);
    unit(s.source_unit);
  }

 private:
  void little_endian(uint64_t x, int size) {
    for (int k = 0; k < size; ++k) bytes.push_back(static_cast<char>((x >> (8 * k)) & 0xff));
  }
};

class Reader {
 public:
  Reader(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw FileError(name_ + ": scene stream " + what + " at byte " + std::to_string(at_));
  }
  size_t left() const { return bytes_.size() - at_; }

  uint64_t little_endian(int size, const char* what) {
    if (left() < static_cast<size_t>(size)) fail(std::string("ends in the middle of ") + what);
    uint64_t x = 0;
    for (int k = 0; k < size; ++k) x |= static_cast<uint64_t>(static_cast<unsigned char>(bytes_[at_ + k])) << (8 * k);
    at_ += size;
    return x;
  }
  uint8_t u8(const char* what) { return static_cast<uint8_t>(little_endian(1, what)); }
  uint32_t u32(const char* what) { return static_cast<uint32_t>(little_endian(4, what)); }
  int i32(const char* what) { return static_cast<int>(static_cast<uint32_t>(little_endian(4, what))); }
  double f64(const char* what) { return std::bit_cast<double>(little_endian(8, what)); }
  bool flag(const char* what) {
    const uint8_t x = u8(what);
    if (x > 1) {
      --at_;
      fail(std::string("has ") + std::to_string(x) + " for the flag " + what + " (0 or 1)");
    }
    return x == 1;
  }
  // A count of items of at least `item_bytes` each: refused when the bytes left cannot hold them, so a
  // damaged count never makes a huge allocation.
  size_t count(size_t item_bytes, const char* what) {
    const uint64_t n = little_endian(8, what);
    if (n > left() / item_bytes) {
      at_ -= 8;
      fail(std::string("count ") + std::to_string(n) + " of " + what + " needs " +
           (n > UINT64_MAX / item_bytes ? std::string("more") : std::to_string(n * item_bytes)) +
           " bytes, more than the " + std::to_string(left() - 8) + " left");
    }
    return static_cast<size_t>(n);
  }
  std::string text(const char* what) {
    const size_t n = count(1, what);
    std::string s(bytes_.substr(at_, n));
    at_ += n;
    return s;
  }
  std::vector<double> doubles(const char* what) {
    std::vector<double> xs(count(8, what));
    for (auto& x : xs) x = f64(what);
    return xs;
  }
  std::vector<Eigen::Vector3d> points(const char* what) {
    std::vector<Eigen::Vector3d> ps(count(24, what));
    for (auto& p : ps) for (int k = 0; k < 3; ++k) p[k] = f64(what);
    return ps;
  }
  std::optional<Colour> colour() {
    if (!flag("colour present")) return std::nullopt;
    Colour c;
    c.r = f64("colour");
    c.g = f64("colour");
    c.b = f64("colour");
    return c;
  }
  LengthUnit unit() {
    LengthUnit u;
    u.name = text("unit name");
    u.millimetres = f64("unit size");
    return u;
  }
  NurbsCurve curve() {
    NurbsCurve c;
    c.dimension = i32("curve dimension");
    c.order = i32("curve order");
    c.knots = doubles("curve knots");
    c.points = points("curve points");
    c.weights = doubles("curve weights");
    return c;
  }
  NurbsSurface surface() {
    NurbsSurface s;
    s.u_order = i32("surface orders");
    s.v_order = i32("surface orders");
    s.u_count = i32("surface counts");
    s.v_count = i32("surface counts");
    s.u_knots = doubles("surface u knots");
    s.v_knots = doubles("surface v knots");
    s.points = points("surface points");
    s.weights = doubles("surface weights");
    return s;
  }
  TrimmedSurface trimmed() {
    TrimmedSurface t;
    t.surface = surface();
    t.loops.resize(count(16, "trimming loops"));  // a loop is two counts at least
    for (auto& loop : t.loops) {
      const size_t segments = count(9, "loop segments");  // a kind and a count at least
      loop.segments.reserve(segments);
      for (size_t n = 0; n < segments; ++n) {
        const uint8_t kind = u8("segment kind");
        if (kind == 0) {
          loop.segments.emplace_back(curve());
        } else if (kind == 1) {
          Polyline2D polyline;
          polyline.points.resize(count(16, "polyline points"));
          for (auto& p : polyline.points) {  // two statements: argument order is unspecified
            p.x() = f64("polyline point");
            p.y() = f64("polyline point");
          }
          loop.segments.emplace_back(std::move(polyline));
        } else {
          --at_;
          fail("has the unknown segment kind " + std::to_string(kind));
        }
      }
      loop.edges.resize(count(5, "loop edges"));
      for (auto& e : loop.edges) {
        e.edge = i32("edge number");
        e.reversed = flag("edge reversed");
      }
    }
    return t;
  }
  Geometry geometry() {
    const uint8_t kind = u8("geometry kind");
    switch (kind) {
      case 0: return trimmed();
      case 1: return curve();
      case 2: {
        TriangleMesh m;
        m.positions = points("mesh positions");
        m.triangles.resize(count(12, "mesh triangles"));
        for (auto& t : m.triangles) for (int& k : t) k = i32("triangle corner");
        m.corner_normals = points("mesh normals");
        return m;
      }
      case 3: {
        PolygonMesh p;
        p.positions = points("polygon positions");
        p.polygons.resize(count(8, "polygons"));
        for (auto& polygon : p.polygons) {
          polygon.resize(count(4, "polygon corners"));
          for (int& k : polygon) k = i32("polygon corner");
        }
        return p;
      }
    }
    --at_;
    fail("has the unknown geometry kind " + std::to_string(kind));
  }
  void node(SceneNode& n, int depth) {
    if (depth > kMaxDepth) fail("nests nodes deeper than " + std::to_string(kMaxDepth));
    n.name = text("node name");
    n.source_entity = text("node source entity");
    for (int k = 0; k < 16; ++k) n.transform.matrix().data()[k] = f64("node transform");
    n.colour = colour();
    // A shape is at least a name, a kind and a few counts; a node at least two names and a transform.
    n.shapes.resize(count(8 + 1 + 1 + 16, "shapes"));
    for (auto& s : n.shapes) {
      s.name = text("shape name");
      s.geometry = geometry();
      s.colour = colour();
      s.source_type = text("shape source type");
      s.source_entity = text("shape source entity");
    }
    n.children.resize(count(16 + 128 + 1 + 16, "child nodes"));
    for (auto& child : n.children) node(child, depth + 1);
  }
  Scene scene() {
    Scene s;
    node(s.root, 0);
    s.unit = unit();
    s.source_unit = unit();
    return s;
  }
  void header(std::string_view magic) {
    if (bytes_.substr(0, magic.size()) != magic)
      throw FileError(name_ + ": not a scene stream (no " + std::string(magic.substr(0, magic.size() - 1)) + " magic)");
    at_ = magic.size();
    const uint32_t version = u32("the version");
    if (version != kVersion) {
      at_ -= 4;
      fail("version " + std::to_string(version) + " is not " + std::to_string(kVersion));
    }
  }
  void end() {
    if (left() != 0) fail("has " + std::to_string(left()) + (left() == 1 ? " byte" : " bytes") + " after its end");
  }

 private:
  std::string_view bytes_;
  const std::string& name_;
  size_t at_ = 0;
};

}  // namespace

std::string write_scene_stream(const Scene& scene) {
  Writer w;
  w.bytes.append(kSceneMagic);
  w.u32(kVersion);
  w.scene(scene);
  return std::move(w.bytes);
}

Scene read_scene_stream(std::string_view bytes, const std::string& name_for_errors) {
  Reader r(bytes, name_for_errors);
  r.header(kSceneMagic);
  Scene scene = r.scene();
  r.end();
  return scene;
}

std::string write_translation_stream(const BrepTranslation& translation) {
  Writer w;
  w.bytes.append(kTranslationMagic);
  w.u32(kVersion);
  w.scene(translation.scene);
  w.u64(translation.fallbacks.size());
  for (const auto& f : translation.fallbacks) {
    w.text(f.node);
    w.i32(f.face_index);
    w.text(f.surface_type);
    w.text(f.reason);
  }
  w.u64(translation.repairs.size());
  for (const auto& line : translation.repairs) w.text(line);
  w.i32(translation.face_count);
  w.u64(translation.degenerated_edges.size());
  for (bool d : translation.degenerated_edges) w.flag(d);
  return std::move(w.bytes);
}

BrepTranslation read_translation_stream(std::string_view bytes, const std::string& name_for_errors) {
  Reader r(bytes, name_for_errors);
  r.header(kTranslationMagic);
  BrepTranslation out;
  out.scene = r.scene();
  out.fallbacks.resize(r.count(8 + 4 + 8 + 8, "fallbacks"));
  for (auto& f : out.fallbacks) {
    f.node = r.text("fallback node");
    f.face_index = r.i32("fallback face");
    f.surface_type = r.text("fallback surface type");
    f.reason = r.text("fallback reason");
  }
  out.repairs.resize(r.count(8, "repairs"));
  for (auto& line : out.repairs) line = r.text("repair");
  out.face_count = r.i32("face count");
  out.degenerated_edges.resize(r.count(1, "degenerated edge flags"));
  for (size_t k = 0; k < out.degenerated_edges.size(); ++k) out.degenerated_edges[k] = r.flag("degenerated edge");
  r.end();
  return out;
}

}  // namespace cadnurbs
