#pragma once
// The control mesh of a quadratic NURSS (non-uniform recursive subdivision surface, Sederberg, Zheng,
// Sewell & Sabin, SIGGRAPH 1998; seed 001 §2.4.6): polygons of any number of sides sharing vertices,
// and knot intervals.
//
// Knot intervals, as the paper puts them for non-uniform Doo-Sabin surfaces: every vertex holds one
// knot interval for each edge incident to it, so an edge {a, b} carries two values, d(a→b) held by a
// and d(b→a) held by b, in general different ("one value per outgoing edge", the thesis's accounting,
// seed 001 §6.1). A quadratic B-spline net is the case where control point P_ij holds its u interval
// on both u edges and its v interval on both v edges; then the eight values around a quad are equal on
// opposite sides (d(P0→P1) = d(P3→P2), d(P1→P0) = d(P2→P3), and likewise across), and the refinement
// rule is tensor-product knot insertion. Where a quad's values are not so (or a vertex's opposite
// edges differ), the paper's general face rule (refine_nurss.hpp) is applied as it stands: it is
// defined for any non-negative intervals. A zero interval makes a crease (the thesis, §2.4.7).
//
// Rational nets: every vertex has a weight (1 unless set); the rules run on homogeneous points
// (w·P, w) and project back, so a rational quadratic NURBS net refines exactly as its NURBS does.
//
// Faces are listed counter-clockwise seen from outside; each directed side a→b belongs to at most one
// face (an orientable manifold mesh); an edge with one face is a boundary edge.
// Every face may carry an integer label (default 0) that refinement hands down to the faces it makes
// (refine_nurss.hpp says how), so that the regions of a limit mesh can be told apart.
#include <Eigen/Core>
#include <compare>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace cadnurbs {

// A typed index into one of NurssMesh's arrays.
template <class Tag>
struct NurssId {
  int value = -1;
  constexpr NurssId() = default;
  constexpr explicit NurssId(int v) : value(v) {}
  auto operator<=>(const NurssId&) const = default;
};
using NurssVertexId = NurssId<struct NurssVertexTag>;
using NurssFaceId = NurssId<struct NurssFaceTag>;
using NurssEdgeId = NurssId<struct NurssEdgeTag>;

struct NurssEdge {
  NurssVertexId ends[2];  // ends[0].value < ends[1].value
  double intervals[2] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  // intervals[s]: the knot interval ends[s] holds on this edge, d(ends[s] → ends[1-s]); NaN until set.
};

class NurssMesh {
 public:
  NurssVertexId add_vertex(const Eigen::Vector3d& position, double weight = 1.0);
  // Adds a face with these corners (counter-clockwise, 3 or more, distinct) and the edges it needs that
  // do not exist yet (their intervals unset). Refuses (GeometryError) repeated corners, an unknown
  // vertex, or a directed side a→b that another face already has (flipped or non-manifold mesh).
  NurssFaceId add_face(const std::vector<NurssVertexId>& corners, int label = 0);
  // Sets d(at → toward). Refuses (GeometryError) a pair that is no edge, or a negative or non-finite value.
  void set_interval(NurssVertexId at, NurssVertexId toward, double interval);

  std::optional<NurssEdgeId> find_edge(NurssVertexId a, NurssVertexId b) const;
  // d(at → toward); refuses (GeometryError) a pair that is no edge.
  double interval(NurssVertexId at, NurssVertexId toward) const;

  int vertex_count() const { return static_cast<int>(positions_.size()); }
  int face_count() const { return static_cast<int>(faces_.size()); }
  int edge_count() const { return static_cast<int>(edges_.size()); }
  const Eigen::Vector3d& position(NurssVertexId v) const { return positions_[v.value]; }
  double weight(NurssVertexId v) const { return weights_[v.value]; }
  // (w·x, w·y, w·z, w): the point the rules average.
  Eigen::Vector4d homogeneous(NurssVertexId v) const;
  const std::vector<NurssVertexId>& corners(NurssFaceId f) const { return faces_[f.value]; }
  int label(NurssFaceId f) const { return labels_[f.value]; }
  // The largest label of `faces` (0 for none): what a face made from them inherits.
  int largest_label(const std::vector<NurssFaceId>& faces) const;
  const NurssEdge& edge(NurssEdgeId e) const { return edges_[e.value]; }
  const std::vector<Eigen::Vector3d>& positions() const { return positions_; }
  // Whether some vertex has a weight other than 1.
  bool is_rational() const;
  // The face that has the directed side a→b, if any.
  std::optional<NurssFaceId> face_with_side(NurssVertexId a, NurssVertexId b) const;
  // Index of v among the corners of f (f must have v).
  int corner_index(NurssFaceId f, NurssVertexId v) const;
  // The faces around v if they close into a ring, in the order where the face having x→v comes just
  // before the face having v→x (the order of v's V-face, refine_nurss.hpp); nullopt for a vertex on the
  // boundary or of no face.
  std::optional<std::vector<NurssFaceId>> ring_of_faces(NurssVertexId v) const;

 private:
  static std::uint64_t key(NurssVertexId a, NurssVertexId b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a.value)) << 32) |
           static_cast<std::uint32_t>(b.value);
  }
  std::vector<Eigen::Vector3d> positions_;
  std::vector<double> weights_;
  std::vector<std::vector<NurssVertexId>> faces_;
  std::vector<int> labels_;
  std::vector<int> a_face_of_vertex_;  // -1: no face yet
  std::vector<NurssEdge> edges_;
  std::unordered_map<std::uint64_t, int> edge_of_pair_;  // key(min, max) -> edge
  std::unordered_map<std::uint64_t, int> face_of_side_;  // key(a, b) -> face with the directed side a→b
};

// Throws GeometryError(entity, reason) unless every edge has both intervals set (finite, >= 0), every
// weight is finite and > 0, every position finite, and no vertex has a closed ring of only two faces
// (its new face would be a two-sided polygon).
void validate(const NurssMesh& mesh, const std::string& entity);

}  // namespace cadnurbs
