// A group of traversal-coded meshes (docs/cnb.md, "Mesh group"): the meshes of one node, typically one per
// colour of a body, coded as one traversal of their union. Meshes coded alone pay twice for the vertices
// along the edges where they meet and start a traversal each; the union shares those vertices, and the
// mesh of each triangle, nearly always the mesh of the triangle across the gate, costs a fraction of a bit.
//
// The union joins vertices of different meshes at the same position (exactly: at a coarse D many vertices
// share a grid point, and joining those would pair unrelated ones), never two of one mesh: the k-th vertex
// of a mesh at a position becomes the k-th union vertex there. So every union vertex holds at most one
// vertex of each mesh, a mesh's triangles keep exactly their own connectivity inside the union, and each
// mesh decodes as it would alone.
#include <array>
#include <map>
#include <string>
#include <vector>

#include "formats/cnb/cnb_geometry.hpp"
#include "formats/cnb/cnb_mesh_copies.hpp"

namespace cadnurbs::cnb {

void write_mesh_group(ByteWriter& out, const GroupCopies& group, double q, CodingState& state) {
  TriangleMesh joined;
  std::vector<int> members;
  using Position = std::array<double, 3>;
  std::map<Position, std::vector<int>> joined_at;  // position -> union vertices there, in order made
  for (size_t m = 0; m < group.kept.size(); ++m) {
    const TriangleMesh& mesh = group.kept[m];
    std::vector<int> joined_vertex(mesh.positions.size(), -1);
    std::map<Position, size_t> taken;  // this mesh's vertices met at each position
    auto vertex = [&](int v) {
      if (joined_vertex[v] >= 0) return joined_vertex[v];
      const auto& p = mesh.positions[v];
      const Position at{p.x(), p.y(), p.z()};
      std::vector<int>& there = joined_at[at];
      const size_t k = taken[at]++;
      if (k == there.size()) {
        there.push_back(static_cast<int>(joined.positions.size()));
        joined.positions.push_back(p);
      }
      return joined_vertex[v] = there[k];
    };
    for (const auto& t : mesh.triangles) {
      joined.triangles.push_back({vertex(t[0]), vertex(t[1]), vertex(t[2])});
      members.push_back(static_cast<int>(m));
    }
  }
  // A copy repeats its source's decoded vertices: they stay where rounding puts them.
  const double free_radius = state.free_radius;
  if (!group.copies.empty()) state.free_radius = 0;
  write_traversal_mesh(out, joined, q, state, group.kept.size() > 1 ? &members : nullptr);  // one: no members
  state.free_radius = free_radius;
  if (!group.copies.empty()) write_piece_copies(out, group.copies);
}

std::vector<TriangleMesh> read_mesh_group(ByteReader& in, int mesh_count, double q, CodingState& state,
                                          bool with_copies, size_t number_room) {
  const size_t start = in.offset();
  std::vector<int> members;
  const TriangleMesh joined = read_traversal_mesh(in, q, state, mesh_count > 1 ? mesh_count : 0, &members);
  members.resize(joined.triangles.size(), 0);
  std::vector<TriangleMesh> meshes(mesh_count);
  std::vector<std::vector<int>> own(mesh_count, std::vector<int>(joined.positions.size(), -1));
  for (size_t t = 0; t < joined.triangles.size(); ++t) {
    TriangleMesh& mesh = meshes[members[t]];
    std::array<int, 3> corners{};
    for (int k = 0; k < 3; ++k) {
      int& v = own[members[t]][joined.triangles[t][k]];
      if (v < 0) {
        v = static_cast<int>(mesh.positions.size());
        mesh.positions.push_back(joined.positions[joined.triangles[t][k]]);
      }
      corners[k] = v;
    }
    mesh.triangles.push_back(corners);
  }
  for (int m = 0; m < mesh_count; ++m)
    if (meshes[m].triangles.empty())
      in.fail("mesh " + std::to_string(m + 1) + " of a group of " + std::to_string(mesh_count) + " has no triangle",
              start);
  if (with_copies) read_piece_copies(in, meshes, q, number_room);
  return meshes;
}

}  // namespace cadnurbs::cnb
