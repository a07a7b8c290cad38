// The driver of tessellate_to_deviation: the faces of a scene (or one surface) through the steps of the
// header, each in its own file under analysis/tessellation/.
#include "analysis/tessellation/tessellate_to_deviation.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "analysis/measure/face_area_check.hpp"
#include "analysis/tessellation/face_meshing.hpp"
#include "analysis/tessellation/grid_planning.hpp"
#include "analysis/tessellation/loop_chord_checks.hpp"
#include "analysis/tessellation/shared_edges.hpp"
#include "analysis/tessellation/tessellation_face.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs {

namespace {

using tessellation::CurveId;
using tessellation::CurveSpan;
using tessellation::CurveUse;
using tessellation::Face;

class Tessellator {
 public:
  Tessellator(std::vector<Face>& faces, double d, TessellationReport& report)
      : faces_(faces), d_(d), report_(report), shared_(faces, d, report) {}

  // `mesh_faces` false: steps 1 and 2 alone (the report's shared-edge figures, no face meshed).
  void run(bool mesh_faces = true) {
    for (auto& f : faces_) guarded(f, [&] { prepare(f); });
    // Step 2: shared edges.
    shared_.find_degenerate_curves();
    shared_.join_vertices();
    const tessellation::ModelCurves& curves = shared_.curves();
    for (int c = 0; c < curves.size(); ++c) {
      if (curves[CurveId{c}].uses.empty()) continue;  // a side replaced by its seam partner
      const CurveUse& first = curves[CurveId{c}].uses.front();
      guarded(faces_[first.face], [&] { shared_.sample_curve(CurveId{c}); });
    }
    // Coarse chords of nearby loops (a small hole near an outer boundary) may cross in (u,v), a
    // small closed edge may come out as fewer than 3 points, and a chord fine on the curve's first
    // face may be too coarse on another: split those chords on their curves, on every face that uses
    // them, until each face's loops are simple and each chord is fine on each face.
    // Only faces that use a split curve change between rounds (`stale`): the others keep their
    // points and have nothing to split.
    std::vector<char> stale(faces_.size(), 1);
    for (int round = 0;; ++round) {
      std::set<CurveSpan> splits;
      for (size_t fi = 0; fi < faces_.size(); ++fi) {
        if (!stale[fi]) continue;
        guarded(faces_[fi], [&] { shared_.collect_loop_points(static_cast<int>(fi)); });
        tessellation::crossing_chords(faces_[fi], splits);
        tessellation::coarse_chords(faces_[fi], d_, splits);
      }
      if (splits.empty() || round == 12) break;
      std::fill(stale.begin(), stale.end(), 0);
      // Descending, so that the spans still to split keep their indices.
      for (auto it = splits.rbegin(); it != splits.rend(); ++it) {
        shared_.split_span(*it);
        for (const CurveUse& use : curves[it->curve].uses) stale[use.face] = 1;
      }
    }
    if (!mesh_faces) return;
    // Steps 3 to 5, face by face.
    for (auto& f : faces_) guarded(f, [&] { tessellation::mesh_face(f, d_, report_); });
    report_.faces += static_cast<int>(faces_.size());
  }

 private:
  std::vector<Face>& faces_;
  double d_;
  TessellationReport& report_;
  tessellation::SharedEdges shared_;

  // Runs `work` for face f; an error names the face.
  template <class F>
  void guarded(Face& f, F&& work) {
    try {
      work();
    } catch (const GeometryError& e) {
      if (e.entity().rfind(f.name, 0) == 0) throw;
      throw GeometryError(f.name, e.what());
    } catch (const std::exception& e) {
      throw GeometryError(f.name, std::string("tessellation failed: ") + e.what());
    }
  }

  // Validation, evaluator and bounds, loops and their model curves, and step 1 (the grid).
  void prepare(Face& f) {
    validate(*f.trimmed, f.name);
    f.eval = std::make_unique<SurfaceEvaluator>(f.trimmed->surface);
    f.bound = surface_deviation_bound(f.trimmed->surface);
    if (f.trimmed->loops.empty()) f.loops.push_back(domain_loop(f.trimmed->surface));
    else f.loops = f.trimmed->loops;
    shared_.add_face(static_cast<int>(&f - faces_.data()));
    std::vector<std::vector<Eigen::Vector2d>> polys;
    // Four points a span: the grid only asks which patches the region reaches, and certification
    // refines wherever the planning fell short.
    for (const auto& loop : f.loops) polys.push_back(loop_polygon(loop, 4));
    tessellation::TessellationGrid grid = tessellation::plan_tessellation_grid(*f.eval, f.bound, polys, d_);
    f.us = std::move(grid.us);
    f.vs = std::move(grid.vs);
  }
};

void check_deviation(double d) {
  if (!(d > 0) || !std::isfinite(d))
    throw GeometryError("tessellate_to_deviation", "the maximum deviation must be a positive number, not " + std::to_string(d));
}

void collect_faces(SceneNode& node, const std::string& path, const Eigen::Affine3d& parent, std::vector<Face>& faces,
                   std::vector<Shape*>& shapes) {
  const Eigen::Affine3d world = parent * node.transform;
  for (size_t i = 0; i < node.shapes.size(); ++i) {
    Shape& shape = node.shapes[i];
    const auto* t = std::get_if<TrimmedSurface>(&shape.geometry);
    if (!t) continue;
    Face f;
    f.trimmed = t;
    f.name = path + "/" + (display_name(shape).empty() ? "shape " + std::to_string(i) : display_name(shape));
    f.world = world;
    faces.push_back(std::move(f));
    shapes.push_back(&shape);
  }
  for (auto& child : node.children) collect_faces(child, path + "/" + display_name(child), world, faces, shapes);
}

}  // namespace

TriangleMesh tessellate_to_deviation(const TrimmedSurface& surface, double max_deviation, TessellationReport* report) {
  check_deviation(max_deviation);
  TessellationReport local;
  std::vector<Face> faces(1);
  faces[0].trimmed = &surface;
  faces[0].name = "surface";
  Tessellator(faces, max_deviation, report ? *report : local).run();
  return std::move(faces[0].mesh);
}

Scene tessellate_to_deviation(const Scene& scene, double max_deviation, TessellationReport* report,
                              bool check_face_areas) {
  check_deviation(max_deviation);
  TessellationReport local;
  TessellationReport& r = report ? *report : local;
  Scene out = scene;
  std::vector<Face> faces;
  std::vector<Shape*> shapes;
  collect_faces(out.root, out.root.name, Eigen::Affine3d::Identity(), faces, shapes);
  Tessellator(faces, max_deviation, r).run();
  if (check_face_areas)
    for (const Face& f : faces)
      if (check_face_area(*f.trimmed, f.mesh, max_deviation).beyond()) {
        ++r.faces_beyond_area_allowance;
        r.uncertified_triangles += static_cast<long>(f.mesh.triangles.size());
      }
  for (size_t i = 0; i < faces.size(); ++i) shapes[i]->geometry = std::move(faces[i].mesh);
  return out;
}

int unshared_edge_uses(const Scene& scene, double max_deviation) {
  check_deviation(max_deviation);
  TessellationReport report;
  Scene faces_of = scene;
  std::vector<Face> faces;
  std::vector<Shape*> shapes;
  collect_faces(faces_of.root, faces_of.root.name, Eigen::Affine3d::Identity(), faces, shapes);
  Tessellator(faces, max_deviation, report).run(false);
  return report.unshared_edge_uses;
}

}  // namespace cadnurbs
