#include "report/nurss_figures.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "analysis/nurss/nurss_from_nurbs.hpp"
#include "analysis/nurss/nurss_limit_mesh.hpp"
#include "formats/nurss/nurss_text.hpp"
#include "analysis/nurss/refine_nurss.hpp"
#include "core/bounding_box.hpp"
#include "core/flatten_transforms.hpp"
#include "core/geometry_error.hpp"
#include "core/planar_polygon_surface.hpp"
#include "formats/common/gzip.hpp"

namespace cadnurbs {

namespace {

// Control points this close to one plane (relative to the part's diagonal) make a planar surface: the
// convex hull property puts the surface in that plane too.
constexpr double kPlanarTolerance = 1e-6;
// Seam and shared-boundary control points this close (relative to the diagonal) become one NURSS vertex.
constexpr double kWeldTolerance = 1e-6;

double distance_from_plane(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : points) centre += p;
  centre /= static_cast<double>(points.size());
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (const auto& p : points) spread += (p - centre) * (p - centre).transpose();
  const Eigen::Vector3d normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(spread).eigenvectors().col(0);
  double farthest = 0;
  for (const auto& p : points) farthest = std::max(farthest, std::abs(normal.dot(p - centre)));
  return farthest;
}

// Whether the loops keep the whole domain: none, or one loop enclosing the domain's area (the four straight
// sides a B-rep reader gives every face).
bool trimmed_by_whole_domain(const TrimmedSurface& t) {
  if (t.loops.empty()) return true;
  if (t.loops.size() != 1) return false;
  const NurbsSurface& s = t.surface;
  const double domain = (s.u_end() - s.u_start()) * (s.v_end() - s.v_start());
  return std::abs(std::abs(loop_signed_area(t.loops[0])) - domain) <= 1e-6 * domain;
}

std::string shape_label(const Shape& shape, int index) {
  const std::string& name = display_name(shape);
  return name.empty() ? "surface " + std::to_string(index) : "surface '" + name + "'";
}

std::optional<NurssFigures> refuse(std::string* why_not, const std::string& reason) {
  if (why_not) *why_not = reason;
  return std::nullopt;
}

}  // namespace

std::optional<NurssFigures> nurss_figures(const Scene& nurbs, double max_deviation, std::string* why_not) {
  const Scene flat = flatten_transforms(nurbs);
  const Eigen::AlignedBox3d box = scene_bounding_box(flat);
  const double diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
  // The quadratic surfaces alone (what the body faces are measured against) and every surface (the whole).
  Scene quadratic, every;
  quadratic.unit = every.unit = flat.unit;
  std::vector<NurbsSurface> nets;
  NurssFigures out;
  int index = 0;
  std::string refusal;
  for_each_shape(flat, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    const int here = index++;
    if (!refusal.empty()) return;
    if (std::holds_alternative<TriangleMesh>(shape.geometry)) {
      refusal = shape_label(shape, here) + " is a triangle mesh; a NURSS is made from NURBS nets";
    } else if (const auto* polygons = std::get_if<PolygonMesh>(&shape.geometry)) {
      for (const auto& polygon : polygons->polygons) {
        std::vector<Eigen::Vector3d> corners;
        for (int k : polygon) corners.push_back(polygons->positions[k]);
        if (auto lid = planar_polygon_surface(corners)) {
          every.root.shapes.push_back({shape.name, std::move(*lid), std::nullopt});
          ++out.lids;
        }
      }
    } else if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
      const NurbsSurface& s = t->surface;
      if (s.u_order == 3 && s.v_order == 3) {
        if (!trimmed_by_whole_domain(*t)) {
          refusal = shape_label(shape, here) + " is trimmed inside its domain; a NURSS is made from whole nets";
          return;
        }
        nets.push_back(s);
        quadratic.root.shapes.push_back(shape);
        ++out.quadratic_surfaces;
      } else if (distance_from_plane(s.points) <= kPlanarTolerance * diagonal) {
        ++out.lids;
      } else {
        refusal = shape_label(shape, here) + " is of order " + std::to_string(s.u_order) + " x " +
                  std::to_string(s.v_order) +
                  " and not planar; a quadratic NURSS needs order 3 x 3 (planar lids become n-gon faces)";
        return;
      }
      every.root.shapes.push_back(shape);
    }
  });
  if (!refusal.empty()) return refuse(why_not, refusal);
  if (nets.empty()) return refuse(why_not, "no order-3 x 3 surface: nothing to make a quadratic NURSS of");
  if (!(max_deviation > 0)) return refuse(why_not, "the maximum deviation must be > 0");

  NurssMesh mesh;
  try {
    mesh = nurss_from_nurbs(nets, kWeldTolerance * diagonal);
    out.ngon_faces = static_cast<int>(fill_boundary_loops(mesh, 1).size());
    validate(mesh, "NURSS mesh");
  } catch (const GeometryError& e) {
    return refuse(why_not, e.what());
  }
  out.text = write_nurss_text(mesh, flat.unit);
  out.text_bytes = static_cast<long>(out.text.size());
  out.gzip_bytes = static_cast<long>(gzip(out.text).size());
  out.storage = nurss_storage(mesh);

  // One refinement step per level tried, not `levels` steps from the start each time.
  NurssMesh refined = mesh;
  for (int levels = 0; levels <= kMostNurssLevels; ++levels) {
    if (levels > 0) refined = refine_nurss(refined);
    NurssTriangles limit = nurss_face_point_mesh(refined);
    const TriangleMesh away = nurss_triangles_with_label(limit, 0);
    if (away.triangles.empty()) continue;  // a coarse net whose every vertex touches an n-gon
    const DeviationMeasure on_body = measure_deviation(away, quadratic);
    if (on_body.mesh_to_surface.max > max_deviation && levels < kMostNurssLevels) continue;
    out.levels = levels;
    out.within_max_deviation = on_body.mesh_to_surface.max <= max_deviation;
    out.away_from_ngons = on_body;
    out.whole = measure_deviation(limit.mesh, every);
    out.limit_mesh = std::move(limit.mesh);
    out.triangle_labels = std::move(limit.triangle_labels);
    break;
  }
  return out;
}

}  // namespace cadnurbs
