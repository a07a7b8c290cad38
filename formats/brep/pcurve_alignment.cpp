#include "formats/brep/pcurve_alignment.hpp"

#include <cmath>
#include <gp_Vec2d.hxx>

namespace cadnurbs {

namespace {

// The period of the surface in u (direction 0) or v (1); 0 when it is neither periodic nor closed.
double period(const Handle(Geom_BSplineSurface)& surface, int direction) {
  Standard_Real u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  if (direction == 0) return surface->IsUPeriodic() || surface->IsUClosed() ? u1 - u0 : 0.0;
  return surface->IsVPeriodic() || surface->IsVClosed() ? v1 - v0 : 0.0;
}

// The surface's point at (u, v), moved by whole periods into its domain first: a B-spline evaluated
// outside its domain extends its end spans, off the closed surface.
gp_Pnt value(const Handle(Geom_BSplineSurface)& surface, const double periods[2], double u, double v) {
  Standard_Real u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  if (periods[0] > 0) u -= std::floor((u - u0) / periods[0]) * periods[0];
  if (periods[1] > 0) v -= std::floor((v - v0) / periods[1]) * periods[1];
  return surface->Value(u, v);
}

}  // namespace

int align_pcurves(const Handle(Geom_BSplineSurface)& surface, std::vector<WireUses>& wires) {
  const double periods[2] = {period(surface, 0), period(surface, 1)};
  if (periods[0] == 0 && periods[1] == 0) return 0;
  int moved = 0;
  for (auto& wire : wires)
    for (size_t i = 1; i < wire.size(); ++i) {
      const gp_Pnt2d end = wire[i - 1].curve->EndPoint(), start = wire[i].curve->StartPoint();
      const double gap[2] = {start.X() - end.X(), start.Y() - end.Y()};
      double whole[2] = {0, 0};
      for (int d = 0; d < 2; ++d) {
        if (periods[d] == 0) continue;
        const double k = std::round(gap[d] / periods[d]);
        if (k != 0 && std::abs(gap[d] - k * periods[d]) <= 1e-3 * periods[d]) whole[d] = k * periods[d];
      }
      if (whole[0] == 0 && whole[1] == 0) continue;
      const double tolerance = 2 * std::max(wire[i - 1].end_tolerance, wire[i].edge_tolerance);
      const gp_Pnt p = value(surface, periods, end.X(), end.Y());
      if (p.Distance(value(surface, periods, start.X(), start.Y())) > tolerance) continue;
      if (value(surface, periods, 0.5 * (end.X() + start.X()), 0.5 * (end.Y() + start.Y())).Distance(p) <= tolerance)
        continue;  // a pole
      wire[i].curve->Translate(gp_Vec2d(-whole[0], -whole[1]));
      ++moved;
    }
  return moved;
}

}  // namespace cadnurbs
