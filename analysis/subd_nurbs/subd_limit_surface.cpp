#include "analysis/subd_nurbs/subd_limit_surface.hpp"

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geometry_error.hpp"

namespace cadnurbs::subd_nurbs {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

namespace {

// The point type OpenSubdiv's refiners and stencils average.
struct OsdPoint {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  void Clear(void* = nullptr) { p.setZero(); }
  void AddWithWeight(const OsdPoint& source, double weight) { p += weight * source.p; }
};

constexpr int kIsolationLevel = 10;  // OpenSubdiv's deepest

using Refiner = std::unique_ptr<Far::TopologyRefiner>;

// OpenSubdiv's refiner of the net under our rules: crease edges infinitely sharp, corners kept, the
// boundary a crease.
Refiner make_refiner(const SubdControlNet& net, const std::string& entity) {
  std::vector<int> sizes, indices, crease_pairs, corners(net.corner_points);
  for (const auto& face : net.faces) {
    sizes.push_back(static_cast<int>(face.size()));
    indices.insert(indices.end(), face.begin(), face.end());
  }
  for (const auto& [a, b] : net.crease_edges) crease_pairs.insert(crease_pairs.end(), {a, b});
  const std::vector<float> crease_sharpness(net.crease_edges.size(), Sdc::Crease::SHARPNESS_INFINITE);
  const std::vector<float> corner_sharpness(corners.size(), Sdc::Crease::SHARPNESS_INFINITE);
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = static_cast<int>(net.points.size());
  descriptor.numFaces = static_cast<int>(net.faces.size());
  descriptor.numVertsPerFace = sizes.data();
  descriptor.vertIndicesPerFace = indices.data();
  descriptor.numCreases = static_cast<int>(net.crease_edges.size());
  descriptor.creaseVertexIndexPairs = crease_pairs.data();
  descriptor.creaseWeights = crease_sharpness.data();
  descriptor.numCorners = static_cast<int>(corners.size());
  descriptor.cornerVertexIndices = corners.data();
  descriptor.cornerWeights = corner_sharpness.data();
  Sdc::Options rules;
  rules.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);  // corners only where tagged
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Refiner refiner(Factory::Create(descriptor, Factory::Options(Sdc::SCHEME_CATMARK, rules)));
  if (!refiner) throw GeometryError(entity, "OpenSubdiv refuses the net's topology");
  return refiner;
}

}  // namespace

struct SubdLimitSurface::Impl {
  std::unique_ptr<Far::TopologyRefiner> refiner;
  std::unique_ptr<Far::PatchTable> table;
  std::unique_ptr<Far::PatchMap> map;
  std::vector<OsdPoint> points;                 // every refined vertex, then the patch table's local points
  std::vector<std::vector<LimitPiece>> pieces;  // per patch
  std::vector<std::array<PatchSide, 4>> sides;  // per patch
};

SubdLimitSurface::SubdLimitSurface(const SubdControlNet& net, const std::string& entity)
    : impl_(std::make_unique<Impl>()) {
  impl_->refiner = make_refiner(net, entity);

  Far::PatchTableFactory::Options options(kIsolationLevel);
  options.useInfSharpPatch = true;                   // creases like boundaries: regular patches beside them
  options.generateLegacySharpCornerPatches = false;  // a smooth boundary corner is isolated, not made sharp
  options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
  options.SetPatchPrecision<double>();
  options.generateVaryingTables = false;
  impl_->refiner->RefineAdaptive(options.GetRefineAdaptiveOptions());
  impl_->table.reset(Far::PatchTableFactory::Create(*impl_->refiner, options));
  impl_->map = std::make_unique<Far::PatchMap>(*impl_->table);

  auto& points = impl_->points;
  const int refined = impl_->refiner->GetNumVerticesTotal();
  points.resize(refined + impl_->table->GetNumLocalPoints());
  for (size_t i = 0; i < net.points.size(); ++i) points[i].p = net.points[i];
  Far::PrimvarRefinerReal<double> primvars(*impl_->refiner);
  OsdPoint* source = points.data();
  for (int level = 1; level <= impl_->refiner->GetMaxLevel(); ++level) {
    OsdPoint* destination = source + impl_->refiner->GetLevel(level - 1).GetNumVertices();
    primvars.Interpolate(level, source, destination);
    source = destination;
  }
  if (const auto* stencils = impl_->table->GetLocalPointStencilTable<double>())
    stencils->UpdateValues(points.data(), points.data() + refined);

  const Far::PtexIndices ptex(*impl_->refiner);
  const int patches = ptex.GetNumFaces();
  impl_->sides.resize(patches);
  for (int f = 0; f < static_cast<int>(net.faces.size()); ++f) {
    int faces[4], edges[4];
    ptex.GetAdjacency(*impl_->refiner, f, 0, faces, edges);
    for (int k = 0; k < 4; ++k) impl_->sides[ptex.GetFaceId(f)][k] = {faces[k], faces[k] < 0 ? -1 : edges[k]};
  }

  impl_->pieces.resize(patches);
  const Far::PatchTable& table = *impl_->table;
  for (int array = 0; array < table.GetNumPatchArrays(); ++array) {
    const bool bspline = table.GetPatchArrayDescriptor(array).GetType() == Far::PatchDescriptor::REGULAR;
    for (int i = 0; i < table.GetNumPatches(array); ++i) {
      const Far::PatchParam param = table.GetPatchParam(array, i);
      LimitPiece piece;
      piece.size = std::ldexp(1.0, -(param.GetDepth() - static_cast<int>(param.NonQuadRoot())));
      piece.u0 = param.GetU() * piece.size;
      piece.v0 = param.GetV() * piece.size;
      if (bspline && param.IsRegular()) {
        const auto cvs = table.GetPatchVertices(array, i);
        std::array<Eigen::Vector3d, 16> grid;
        for (int k = 0; k < 16; ++k)
          grid[k] = cvs[k] >= 0 ? points[cvs[k]].p : Eigen::Vector3d::Zero();  // phantoms: below
        // Boundary bits, side k = 0..3 (v = 0, u = 1, v = 1, u = 0): the row beyond is the phantom 2 P1 - P2.
        const int boundary = param.GetBoundary();
        auto at = [&](int u, int v) -> Eigen::Vector3d& { return grid[u + 4 * v]; };
        for (int t = 0; t < 4; ++t) {
          if (boundary & 1) at(t, 0) = 2 * at(t, 1) - at(t, 2);
          if (boundary & 4) at(t, 3) = 2 * at(t, 2) - at(t, 1);
        }
        for (int t = 0; t < 4; ++t) {
          if (boundary & 8) at(0, t) = 2 * at(1, t) - at(2, t);
          if (boundary & 2) at(3, t) = 2 * at(2, t) - at(1, t);
        }
        piece.bspline = grid;
      }
      impl_->pieces[param.GetFaceId()].push_back(piece);
    }
  }
}

SubdLimitSurface::~SubdLimitSurface() = default;

int SubdLimitSurface::patch_count() const { return static_cast<int>(impl_->sides.size()); }

Eigen::Vector3d SubdLimitSurface::point(int patch, double u, double v) const {
  const Far::PatchTable::PatchHandle* handle = impl_->map->FindPatch(patch, u, v);
  if (!handle)
    throw GeometryError("subd limit surface", "no patch at (" + std::to_string(u) + ", " + std::to_string(v) + ")");
  double weights[20];
  impl_->table->EvaluateBasis(*handle, u, v, weights);
  const auto cvs = impl_->table->GetPatchVertices(*handle);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < cvs.size(); ++k) sum += weights[k] * impl_->points[cvs[k]].p;
  return sum;
}

const std::vector<LimitPiece>& SubdLimitSurface::pieces(int patch) const { return impl_->pieces[patch]; }

PatchSide SubdLimitSurface::neighbour(int patch, int side) const { return impl_->sides[patch][side]; }

}  // namespace cadnurbs::subd_nurbs
