#pragma once
// What a part costs and how close it comes as a quadratic NURSS (seed 001 §5.2, §6.1), for the storage
// report: the part's order-3 x 3 NURBS nets become one NURSS (nurss_from_nurbs), its handrail-connection
// holes n-gon faces (fill_boundary_loops, label 1) in place of the planar lids, and the NURSS is refined
// until its limit mesh lies within the asked deviation of the NURBS away from the n-gons.
//
// In:  a scene of NURBS surfaces (world transforms applied here), and D in the scene's unit.
//      Every surface must be either order 3 x 3 and untrimmed (or trimmed by its whole domain: the four
//      straight sides a STEP/IGES reader gives), or planar of any order (a lid, which an n-gon replaces);
//      exact planar polygons (PolygonMesh) count as lids too. Curves are ignored.
// Out: empty, with the reason in *why_not, when a surface is neither (e.g. a bilinear twisted patch, a
//      cubic), a quadratic surface is trimmed inside its domain, there is no quadratic surface, the scene
//      holds a triangle mesh, or nurss_from_nurbs / fill_boundary_loops refuse the nets (their message).
//      Otherwise the figures below. Levels are tried from 0 up to kMostNurssLevels; the first whose
//      triangles from body faces measure within D of the quadratic surfaces (mesh -> surface) is kept, or
//      the last one with within_max_deviation false.
// Measuring (analysis/measure/measure_deviation, sampled, default spacing: a third of the mean edge length, so
// that every triangle's inside is sampled at every level):
//  - away_from_ngons: the limit mesh's triangles from body faces only (label 0) against the quadratic
//    surfaces; its mesh_to_surface is the criterion (the body next to an n-gon is covered by n-gon
//    triangles, so the other direction is not asked there);
//  - whole: the whole limit mesh against every surface (quadratic + lids), both ways: where the n-gons
//    differ from the trimmed lids and the rounded corners next to them.
#include <optional>
#include <string>
#include <vector>

#include "analysis/measure/measure_deviation.hpp"
#include "analysis/nurss/nurss_storage.hpp"
#include "core/scene.hpp"

namespace cadnurbs {

constexpr int kMostNurssLevels = 6;

struct NurssFigures {
  std::string text;                // the control mesh as written (nurss_text.hpp, docs/nurss.md; exact numbers)
  long text_bytes = 0, gzip_bytes = 0;
  NurssStorage storage;            // the thesis's counts of that control mesh (nurss_storage.hpp)
  int quadratic_surfaces = 0, lids = 0, ngon_faces = 0;
  int levels = 0;                  // refinement levels of the limit mesh below
  bool within_max_deviation = false;
  TriangleMesh limit_mesh;         // world coordinates, the scene's unit
  std::vector<int> triangle_labels;  // per triangle: 0 from body faces, 1 from n-gons
  DeviationMeasure away_from_ngons;  // see above
  DeviationMeasure whole;
};

std::optional<NurssFigures> nurss_figures(const Scene& nurbs, double max_deviation, std::string* why_not = nullptr);

}  // namespace cadnurbs
