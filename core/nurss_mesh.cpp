#include "core/nurss_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry_error.hpp"

namespace cadnurbs {

NurssVertexId NurssMesh::add_vertex(const Eigen::Vector3d& position, double weight) {
  positions_.push_back(position);
  weights_.push_back(weight);
  a_face_of_vertex_.push_back(-1);
  return NurssVertexId(vertex_count() - 1);
}

NurssFaceId NurssMesh::add_face(const std::vector<NurssVertexId>& corners, int label) {
  const std::string entity = "NURSS face " + std::to_string(face_count());
  const int n = static_cast<int>(corners.size());
  if (n < 3) throw GeometryError(entity, "has " + std::to_string(n) + " corners; a face needs 3 or more");
  for (int k = 0; k < n; ++k) {
    if (corners[k].value < 0 || corners[k].value >= vertex_count())
      throw GeometryError(entity, "corner " + std::to_string(k) + " names no vertex");
    for (int l = 0; l < k; ++l)
      if (corners[l] == corners[k])
        throw GeometryError(entity, "repeats vertex " + std::to_string(corners[k].value));
  }
  for (int k = 0; k < n; ++k) {
    const NurssVertexId a = corners[k], b = corners[(k + 1) % n];
    if (face_of_side_.count(key(a, b)))
      throw GeometryError(entity, "side " + std::to_string(a.value) + "->" + std::to_string(b.value) +
                                      " is already a side of face " + std::to_string(face_of_side_.at(key(a, b))) +
                                      " (faces flipped or more than two on an edge)");
  }
  const int f = face_count();
  for (int k = 0; k < n; ++k) {
    const NurssVertexId a = corners[k], b = corners[(k + 1) % n];
    face_of_side_[key(a, b)] = f;
    const NurssVertexId lo = std::min(a, b), hi = std::max(a, b);
    if (!edge_of_pair_.count(key(lo, hi))) {
      edge_of_pair_[key(lo, hi)] = edge_count();
      NurssEdge e;
      e.ends[0] = lo;
      e.ends[1] = hi;
      edges_.push_back(e);
    }
  }
  faces_.push_back(corners);
  labels_.push_back(label);
  for (NurssVertexId v : corners)
    if (a_face_of_vertex_[v.value] < 0) a_face_of_vertex_[v.value] = f;
  return NurssFaceId(f);
}

std::optional<NurssEdgeId> NurssMesh::find_edge(NurssVertexId a, NurssVertexId b) const {
  const auto it = edge_of_pair_.find(key(std::min(a, b), std::max(a, b)));
  if (it == edge_of_pair_.end()) return std::nullopt;
  return NurssEdgeId(it->second);
}

void NurssMesh::set_interval(NurssVertexId at, NurssVertexId toward, double interval) {
  const auto e = find_edge(at, toward);
  const std::string entity = "NURSS edge " + std::to_string(at.value) + "-" + std::to_string(toward.value);
  if (!e) throw GeometryError(entity, "is no edge of the mesh");
  if (!std::isfinite(interval) || interval < 0)
    throw GeometryError(entity, "knot interval " + std::to_string(interval) + " is not a finite value >= 0");
  NurssEdge& edge = edges_[e->value];
  edge.intervals[edge.ends[0] == at ? 0 : 1] = interval;
}

double NurssMesh::interval(NurssVertexId at, NurssVertexId toward) const {
  const auto e = find_edge(at, toward);
  if (!e)
    throw GeometryError("NURSS edge " + std::to_string(at.value) + "-" + std::to_string(toward.value),
                        "is no edge of the mesh");
  const NurssEdge& edge = edges_[e->value];
  return edge.intervals[edge.ends[0] == at ? 0 : 1];
}

Eigen::Vector4d NurssMesh::homogeneous(NurssVertexId v) const {
  const double w = weights_[v.value];
  const Eigen::Vector3d& p = positions_[v.value];
  return {w * p.x(), w * p.y(), w * p.z(), w};
}

bool NurssMesh::is_rational() const {
  return std::any_of(weights_.begin(), weights_.end(), [](double w) { return w != 1.0; });
}

std::optional<NurssFaceId> NurssMesh::face_with_side(NurssVertexId a, NurssVertexId b) const {
  const auto it = face_of_side_.find(key(a, b));
  if (it == face_of_side_.end()) return std::nullopt;
  return NurssFaceId(it->second);
}

int NurssMesh::largest_label(const std::vector<NurssFaceId>& faces) const {
  int label = 0;
  for (NurssFaceId f : faces) label = std::max(label, labels_[f.value]);
  return label;
}

int NurssMesh::corner_index(NurssFaceId f, NurssVertexId v) const {
  const auto& c = faces_[f.value];
  return static_cast<int>(std::find(c.begin(), c.end(), v) - c.begin());
}

std::optional<std::vector<NurssFaceId>> NurssMesh::ring_of_faces(NurssVertexId v) const {
  if (a_face_of_vertex_[v.value] < 0) return std::nullopt;
  const NurssFaceId start(a_face_of_vertex_[v.value]);
  std::vector<NurssFaceId> ring;
  NurssFaceId f = start;
  while (ring.size() <= faces_.size()) {
    ring.push_back(f);
    const auto& c = faces_[f.value];
    const int n = static_cast<int>(c.size());
    const auto next = face_with_side(v, c[(corner_index(f, v) + n - 1) % n]);
    if (!next) return std::nullopt;
    if (*next == start) return ring;
    f = *next;
  }
  return std::nullopt;  // not reached on a valid mesh: each face is met once around v
}

void validate(const NurssMesh& mesh, const std::string& entity) {
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    const NurssVertexId id(v);
    if (!mesh.position(id).allFinite())
      throw GeometryError(entity, "vertex " + std::to_string(v) + " has a non-finite position");
    if (!std::isfinite(mesh.weight(id)) || mesh.weight(id) <= 0)
      throw GeometryError(entity, "vertex " + std::to_string(v) + " has weight " + std::to_string(mesh.weight(id)) +
                                      "; weights must be > 0");
  }
  for (int e = 0; e < mesh.edge_count(); ++e) {
    const NurssEdge& edge = mesh.edge(NurssEdgeId(e));
    for (int s = 0; s < 2; ++s)
      if (!std::isfinite(edge.intervals[s]) || edge.intervals[s] < 0)
        throw GeometryError(entity, "edge " + std::to_string(edge.ends[0].value) + "-" +
                                        std::to_string(edge.ends[1].value) + ": vertex " +
                                        std::to_string(edge.ends[s].value) + " holds no knot interval >= 0");
  }
  // A closed ring of two faces around a vertex: both faces have the sides a→v and v→a of the same two edges.
  for (int f = 0; f < mesh.face_count(); ++f) {
    const auto& c = mesh.corners(NurssFaceId(f));
    const int n = static_cast<int>(c.size());
    for (int k = 0; k < n; ++k) {
      const NurssVertexId v = c[k], next = c[(k + 1) % n], prev = c[(k + n - 1) % n];
      const auto g = mesh.face_with_side(next, v), h = mesh.face_with_side(v, prev);
      if (g && h && *g == *h)
        throw GeometryError(entity, "vertex " + std::to_string(v.value) +
                                        " is surrounded by two faces only; its new face would have two sides");
    }
  }
}

}  // namespace cadnurbs
