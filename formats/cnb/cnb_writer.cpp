#include "formats/cnb/cnb_writer.hpp"

#include <algorithm>
#include <cmath>

#include "formats/cnb/cnb_container.hpp"
#include "formats/cnb/cnb_geometry.hpp"
#include "formats/cnb/cnb_quantisation.hpp"
#include "formats/cnb/cnb_scene_layout.hpp"

namespace cadnurbs {

namespace {

using namespace cnb;

struct SceneEncoder {
  ByteWriter out;
  const CnbOptions& options;
  double q;
  CnbWriteReport& report;
  int previous_edge = -1;

  void colour(const Colour& c) {
    for (double v : {c.r, c.g, c.b}) out.varuint(static_cast<uint64_t>(std::lround(std::clamp(v, 0.0, 1.0) * 65535.0)), Field::raw);
  }

  void shape(const Shape& s, double world_scale) {
    const uint8_t kind = static_cast<uint8_t>(s.geometry.index());
    out.byte(static_cast<uint8_t>(kind | (s.colour ? has_colour_flag : 0)), Field::structure);
    out.text(s.name);
    if (s.colour) colour(*s.colour);
    if (const auto* t = std::get_if<TrimmedSurface>(&s.geometry)) {
      const bool parallelogram = write_surface(out, t->surface, q);
      ++(parallelogram ? report.parallelogram_nets : report.row_nets);
      const int e = trim_step_exponent(t->surface, options, world_scale);
      out.varsint(e, Field::structure);
      write_trim_loops(out, t->loops, e, previous_edge);
      if (!t->loops.empty()) report.trim_bound = std::max(report.trim_bound, trim_bound(t->surface, e, world_scale));
    } else if (const auto* c = std::get_if<NurbsCurve>(&s.geometry)) {
      write_curve(out, *c, q);
    } else if (const auto* m = std::get_if<TriangleMesh>(&s.geometry)) {
      write_triangle_mesh(out, *m, q);
    } else {
      write_polygon_mesh(out, std::get<PolygonMesh>(s.geometry), q);
    }
  }

  void node(const SceneNode& n, const Eigen::Affine3d& parent) {
    const Eigen::Affine3d world = parent * n.transform;
    const bool linear = !n.transform.linear().isIdentity(0.0);
    const bool translation = !n.transform.translation().isZero(0.0);
    out.text(n.name);
    out.byte(static_cast<uint8_t>((n.colour ? node_colour_flag : 0) | (linear ? node_linear_flag : 0) |
                                  (translation ? node_translation_flag : 0)),
             Field::structure);
    if (n.colour) colour(*n.colour);
    if (linear)
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) out.float64(n.transform.linear()(r, c));
    if (translation)
      for (int k = 0; k < 3; ++k) out.float64(n.transform.translation()(k));
    out.varuint(n.shapes.size(), Field::count);
    const double scale = transform_scale(world);
    for (const auto& s : n.shapes) shape(s, scale);
    out.varuint(n.children.size(), Field::count);
    for (const auto& child : n.children) node(child, world);
  }
};

}  // namespace

std::string write_cnb(const Scene& scene, const CnbOptions& options, CnbWriteReport* report) {
  validate(scene);
  CnbWriteReport local;
  CnbWriteReport& r = report ? *report : local;
  r = CnbWriteReport{};
  const double q = point_step(scene, options);
  r.point_step = q;
  r.point_bound = q * std::sqrt(3.0) / 2.0 * largest_world_scale(scene);
  SceneEncoder encoder{ByteWriter{}, options, q, r};
  encoder.node(scene.root, Eigen::Affine3d::Identity());
  // The scene header goes first; it states the bound, known once every face's trim grid is chosen.
  ByteWriter header;
  header.text(scene.unit.name);
  header.float64(scene.unit.millimetres);
  header.text(scene.source_unit.name);
  header.float64(scene.source_unit.millimetres);
  header.float64(options.max_deviation);
  header.float64(q);
  header.float64(r.deviation_bound());
  ByteWriter payload = header;
  payload.append(encoder.out);
  return pack(payload, options.coder, &r);
}

}  // namespace cadnurbs
