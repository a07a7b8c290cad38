#include "formats/brep/face_to_trimmed_surface.hpp"

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BezierSurface.hxx>
#include <NCollection_DataMap.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/geometry_error.hpp"
#include "core/loop_closure.hpp"
#include "core/loop_orientation.hpp"
#include "core/mirror_in_u.hpp"
#include "core/number_format.hpp"
#include "formats/brep/direct_face.hpp"
#include "formats/brep/face_pcurves.hpp"
#include "formats/brep/occt_errors.hpp"
#include "formats/brep/occt_to_nurbs.hpp"
#include "formats/brep/pcurve_alignment.hpp"

namespace cadnurbs {

namespace {

// The converted face's surface as a B-spline with the same parameterization as its pcurves.
Handle(Geom_BSplineSurface) bspline_surface(const TopoDS_Face& face) {
  Handle(Geom_Surface) surface = BRep_Tool::Surface(face);  // location applied
  if (surface.IsNull()) throw FaceConversionError("the face has no surface");
  if (auto bspline = Handle(Geom_BSplineSurface)::DownCast(surface))
    return Handle(Geom_BSplineSurface)::DownCast(bspline->Copy());
  // A Bezier patch converts with its parameters unchanged; anything else would move the pcurves.
  if (surface->IsKind(STANDARD_TYPE(Geom_BezierSurface))) return GeomConvert::SurfaceToBSplineSurface(surface);
  throw FaceConversionError(std::string("NurbsConvert left a ") + surface->DynamicType()->Name() +
                            " surface unconverted");
}

// Range of the pcurves in u (direction 0) or v (1), from samples (control polygons overshoot).
std::pair<double, double> pcurve_range(const std::vector<WireUses>& wires, int direction) {
  double lo = Precision::Infinite(), hi = -Precision::Infinite();
  for (const auto& wire : wires)
    for (const auto& use : wire) {
      const int n = std::max(8, 4 * use.curve->NbPoles());
      const double a = use.curve->FirstParameter(), b = use.curve->LastParameter();
      for (int i = 0; i <= n; ++i) {
        const gp_Pnt2d p = use.curve->Value(a + (b - a) * i / n);
        const double x = direction == 0 ? p.X() : p.Y();
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
    }
  return {lo, hi};
}

void shift_pcurves(std::vector<WireUses>& wires, int direction, double amount) {
  const gp_Vec2d shift = direction == 0 ? gp_Vec2d(amount, 0) : gp_Vec2d(0, amount);
  for (auto& wire : wires)
    for (auto& use : wire) use.curve->Translate(shift);
}

// A closed, non-periodic surface (NurbsConvert of a full cylinder) whose pcurves run past one of its
// ends by less than a period (its seam is not the face's): the surface restarts where the pcurves
// start (a knot of full multiplicity there made the periodic origin), and the pcurves move by whole
// periods into it.
void rebase_closed(Handle(Geom_BSplineSurface)& surface, std::vector<WireUses>& wires, int direction) {
  if (wires.empty() || !(direction == 0 ? surface->IsUClosed() : surface->IsVClosed())) return;
  Standard_Real u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  const double a = direction == 0 ? u0 : v0, b = direction == 0 ? u1 : v1, period = b - a, tol = 1e-9 * period;
  const auto [lo, hi] = pcurve_range(wires, direction);
  if ((lo >= a - tol && hi <= b + tol) || hi - lo > period + tol) return;
  const double start = lo + std::floor((lo - a) / period) * -period;  // lo moved into [a, b)
  Handle(Geom_BSplineSurface) copy = Handle(Geom_BSplineSurface)::DownCast(surface->Copy());
  try {
    if (direction == 0) {
      copy->SetUPeriodic();
      copy->InsertUKnot(start, copy->UDegree(), tol);
      for (int i = 1; i <= copy->NbUKnots(); ++i)
        if (std::abs(copy->UKnot(i) - start) <= tol) copy->SetUOrigin(i);
      copy->SetUNotPeriodic();
    } else {
      copy->SetVPeriodic();
      copy->InsertVKnot(start, copy->VDegree(), tol);
      for (int i = 1; i <= copy->NbVKnots(); ++i)
        if (std::abs(copy->VKnot(i) - start) <= tol) copy->SetVOrigin(i);
      copy->SetVNotPeriodic();
    }
  } catch (const Standard_Failure&) {
    return;  // left as it is: the tessellator reports the loop outside the domain
  }
  copy->Bounds(u0, u1, v0, v1);
  const double c = direction == 0 ? u0 : v0, d = direction == 0 ? u1 : v1;
  const double shift = std::round((c - lo) / period) * period;
  if (std::abs(lo + shift - c) > 1e-6 * period || hi + shift > d + 1e-6 * period) return;
  surface = copy;
  if (shift != 0) shift_pcurves(wires, direction, shift);
}

// Makes the surface non-periodic while keeping every pcurve inside its domain: the pcurves move by whole
// periods when that fits them in, otherwise the surface is re-based to start where the face starts.
void unperiodize(Handle(Geom_BSplineSurface)& surface, std::vector<WireUses>& wires) {
  for (int direction = 0; direction < 2; ++direction) {
    const bool periodic = direction == 0 ? surface->IsUPeriodic() : surface->IsVPeriodic();
    if (!periodic) {
      rebase_closed(surface, wires, direction);
      continue;
    }
    Standard_Real u0, u1, v0, v1;
    surface->Bounds(u0, u1, v0, v1);
    const double a = direction == 0 ? u0 : v0, b = direction == 0 ? u1 : v1;
    const double period = b - a, tol = 1e-9 * period;
    if (!wires.empty()) {
      auto [lo, hi] = pcurve_range(wires, direction);
      if (lo < a - tol || hi > b + tol) {
        const double k = std::floor((lo - a + tol) / period);
        if (hi - k * period <= b + tol) {
          shift_pcurves(wires, direction, -k * period);
        } else {
          // The face crosses the seam of the parameterization: start the surface where the face starts.
          hi = std::min(hi, lo + period);
          if (direction == 0)
            surface->Segment(lo, hi, v0, v1);
          else
            surface->Segment(u0, u1, lo, hi);
        }
      }
    }
    if (direction == 0 && surface->IsUPeriodic()) surface->SetUNotPeriodic();
    if (direction == 1 && surface->IsVPeriodic()) surface->SetVNotPeriodic();
  }
}

// The surface point at uv moved onto the domain, as every later step evaluates it: OCCT extrapolates
// outside, which made a (u,v) gap of 5e-6 just past a domain's edge "3.34e+03 mm" in 3D.
gp_Pnt clamped_value(const Handle(Geom_BSplineSurface)& surface, const Eigen::Vector2d& uv) {
  Standard_Real u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  return surface->Value(std::clamp(uv.x(), u0, u1), std::clamp(uv.y(), v0, v1));
}

// The wire as a closed core loop: gaps within the 3D tolerance are closed, by moving the segment ends
// when small in (u, v), by a straight bridge when the gap is long in (u, v) but one point in 3D.
TrimLoop close_wire(const WireUses& uses, const Handle(Geom_BSplineSurface)& surface, double domain_size,
                    int wire_number) {
  TrimLoop out;
  for (const auto& use : uses) {
    out.segments.emplace_back(to_nurbs_curve_2d(use.curve));
    out.edges.push_back(use.ref);
  }
  const size_t n = out.segments.size();
  // Joint i: end of segment i, start of segment i + 1. Bridges are inserted after the loop is scanned.
  std::vector<std::pair<size_t, Polyline2D>> bridges;
  for (size_t i = 0; i < n; ++i) {
    const size_t next = (i + 1) % n;
    const Eigen::Vector2d end = segment_end(out.segments[i]), start = segment_start(out.segments[next]);
    const double gap = (end - start).norm();
    if (gap == 0.0) continue;
    if (gap <= 1e-7 * domain_size) {
      join_segments(out.segments[i], out.segments[next]);
      continue;
    }
    // The vertex joins the two edges; each pcurve may be off by its edge's tolerance.
    // Both pcurve ends lie within the tolerance of the vertex, so up to twice it apart.
    const double tolerance = 2 * std::max(uses[i].end_tolerance, uses[next].edge_tolerance);
    const gp_Pnt p = clamped_value(surface, end);
    const double distance = p.Distance(clamped_value(surface, start));
    if (distance > tolerance)
      throw FaceConversionError("wire " + std::to_string(wire_number) + " does not close: gap " + message_number(gap) +
                                " in (u,v) between its segments " + std::to_string(i + 1) + " and " +
                                std::to_string(next + 1) + ", " + message_number(distance) +
                                " in 3D, above the tolerance " + message_number(tolerance));
    if (gap <= 1e-4 * domain_size) {
      join_segments(out.segments[i], out.segments[next]);
      continue;
    }
    for (int k = 1; k < 8; ++k) {
      const Eigen::Vector2d q = end + (start - end) * (k / 8.0);
      if (clamped_value(surface, q).Distance(p) > tolerance)
        throw FaceConversionError("wire " + std::to_string(wire_number) + " does not close: gap " +
                                  message_number(gap) + " in (u,v) between its segments " + std::to_string(i + 1) +
                                  " and " + std::to_string(next + 1) + " is not a degenerated point");
    }
    bridges.emplace_back(i, Polyline2D{{end, start}});
  }
  for (auto it = bridges.rbegin(); it != bridges.rend(); ++it) {
    out.segments.insert(out.segments.begin() + static_cast<long>(it->first) + 1, it->second);
    out.edges.insert(out.edges.begin() + static_cast<long>(it->first) + 1, TrimEdgeRef{});
  }
  return out;
}

// Runs one step of the conversion, naming the step in what OCCT throws (its messages are often empty).
template <class Step>
auto step(const char* name, Step&& run) {
  try {
    return run();
  } catch (const Standard_Failure& failure) {
    throw FaceConversionError(std::string(name) + ": " + occt_failure_text(failure));
  }
}

// The face through BRepBuilderAPI_NurbsConvert: every surface type, pcurves recomputed by projection
// where the surface's parameterization changes.
BSplineFace nurbs_converted_face(const TopoDS_Face& face, EdgeNumbering& edges) {
  BRepBuilderAPI_NurbsConvert convert;
  step("BRepBuilderAPI_NurbsConvert", [&] {
    convert.Perform(face, /*Copy=*/true);
    return 0;
  });
  if (!convert.IsDone()) throw FaceConversionError("BRepBuilderAPI_NurbsConvert failed");
  const TopoDS_Face converted = TopoDS::Face(convert.Shape());

  // The converted edges keep the direction of their source edges; only their identity changes.
  NCollection_DataMap<TopoDS_Shape, int, TopTools_ShapeMapHasher> origin;
  TopTools_IndexedMapOfShape source_edges;
  TopExp::MapShapes(face, TopAbs_EDGE, source_edges);
  for (int i = 1; i <= source_edges.Extent(); ++i) {
    const TopoDS_Edge& edge = TopoDS::Edge(source_edges(i));
    origin.Bind(convert.ModifiedShape(edge), edges.number(edge));
  }
  BSplineFace out;
  out.surface = step("surface", [&] { return bspline_surface(converted); });
  const TopoDS_Face forward = TopoDS::Face(converted.Oriented(TopAbs_FORWARD));
  out.wires = step("pcurves", [&] {
    return face_pcurves(
        forward,
        [&](const TopoDS_Edge& edge) {
          const int* number = origin.Seek(edge);
          if (!number) throw FaceConversionError("an edge of the converted face has no source edge");
          return *number;
        },
        trimmed_bspline);
  });
  return out;
}

}  // namespace

TrimmedSurface face_to_trimmed_surface(const TopoDS_Face& face, EdgeNumbering& edges) {
  // B-spline faces, and analytic faces bounded by iso-lines (most planes, cylinders and cones of machined
  // parts), convert exactly and fast; the rest go through OCCT's NurbsConvert, whose pcurve projections cost
  // far more.
  std::optional<BSplineFace> direct;
  try {
    direct = direct_face(face, edges);
  } catch (const Standard_Failure&) {
    // OCCT refused the direct route (e.g. an unbounded face); NurbsConvert may still manage.
  }
  BSplineFace converted = direct ? std::move(*direct) : nurbs_converted_face(face, edges);
  Handle(Geom_BSplineSurface)& surface = converted.surface;
  std::vector<WireUses>& wires = converted.wires;
  step("unperiodizing", [&] {
    align_pcurves(surface, wires);
    unperiodize(surface, wires);
    return 0;
  });

  TrimmedSurface out;
  out.surface = to_nurbs_surface(surface);
  const double domain_size = std::max(out.surface.u_end() - out.surface.u_start(),
                                      out.surface.v_end() - out.surface.v_start());
  for (size_t w = 0; w < wires.size(); ++w)
    out.loops.push_back(close_wire(wires[w], surface, domain_size, static_cast<int>(w) + 1));

  if (face.Orientation() == TopAbs_REVERSED) mirror_in_u(out);
  orient_loops(out.loops);
  validate(out, "face");
  return out;
}

}  // namespace cadnurbs
