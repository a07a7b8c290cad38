#include "formats/3dm/subd_object.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry_error.hpp"
#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {
namespace {

[[noreturn]] void refuse(const ArchiveReader& reader, const std::string& reason) { reader.fail("ON_SubD: " + reason); }

// Archive ids, ids, level; 60: two flagged optional points and the end byte; 70: the addition end mark.
constexpr std::size_t kMinComponentBytes = 11;
constexpr int kLimitPointMark = 4;  // the flag byte before a vertex's cached limit points
constexpr std::uint8_t kAdditionsEnd = 255;
constexpr std::uint8_t kAdditionChunk = 254;

// Per ON_SubDVertexTag value (Unset, Smooth, Crease, Corner, Dart): whether it is a corner, the one tag
// the net says; the others follow from the crease edges.
constexpr std::array kVertexTagIsCorner = {false, false, false, true, false};

// ON_SubDEdgeTag by value: Unset, Smooth, Crease, (3 unused), SmoothX (smooth, subdivided at its middle).
struct EdgeTag {
  bool valid;
  bool crease;
};
constexpr std::array kEdgeTags = {EdgeTag{true, false}, EdgeTag{true, false}, EdgeTag{true, true},
                                  EdgeTag{false, false}, EdgeTag{true, false}};

// A reference to another component: its archive id and the pointer's flag bits.
struct Reference {
  std::uint32_t archive_id = 0;
  std::uint8_t flags = 0;
};

Reference read_reference(ArchiveReader& reader) {
  const std::uint32_t id = reader.u32();
  return {id, reader.u8()};
}

// The archive ids [begin, end) one kind of component of the level has.
struct IdRange {
  const char* kind;
  std::uint32_t begin = 0, end = 0;
  std::size_t size() const { return end - begin; }
  int index_of(const ArchiveReader& reader, const std::string& who, std::uint32_t archive_id) const {
    if (archive_id < begin || archive_id >= end)
      refuse(reader, who + " refers to " + kind + " archive id " + std::to_string(archive_id) + ", outside [" +
                         std::to_string(begin) + ", " + std::to_string(end) + ")");
    return static_cast<int>(archive_id - begin);
  }
};

// Version 70's additions: size bytes, each followed by that much data (0: nothing), an anonymous chunk
// (254), up to the end mark (255). Every pass reads a byte, so this ends within the chunk.
void skip_additions(ArchiveReader& reader) {
  for (std::uint8_t size = reader.u8(); size != kAdditionsEnd; size = reader.u8()) {
    if (size == kAdditionChunk) {
      reader.begin_chunk(tcode::kAnonymousChunk);
      reader.end_chunk();
    } else {
      reader.skip(size);
    }
  }
}

void finish_component(ArchiveReader& reader, const std::string& who) {
  if (reader.archive_version() >= 70) return skip_additions(reader);
  const std::uint8_t end = reader.u8();
  if (end != 0) refuse(reader, who + " ends in byte " + std::to_string(end) + ", not 0");
}

// What every component starts with: archive id, id, subdivision level, then (60) an optional cached
// subdivision point and a never-used optional point, or (70) additions.
void read_component_base(ArchiveReader& reader, const std::string& who, std::uint32_t expected_archive_id) {
  const std::uint32_t archive_id = reader.u32();
  reader.u32();  // the component's id, which Rhino shows the user; the net numbers by position
  const std::uint16_t level = reader.u16();
  if (archive_id != expected_archive_id)
    refuse(reader,
           who + " has archive id " + std::to_string(archive_id) + ", expected " + std::to_string(expected_archive_id));
  if (level != 0) refuse(reader, who + " is on level " + std::to_string(level) + ", expected 0");
  if (reader.archive_version() >= 70) return skip_additions(reader);
  for (int k = 0; k < 2; ++k)
    if (reader.u8() != 0) reader.skip(3 * 8);
}

// A u16 count and that many references, whose targets are not needed.
void skip_references(ArchiveReader& reader) { reader.skip(std::size_t{reader.u16()} * 5); }

void read_vertex(ArchiveReader& reader, const IdRange& vertices, int index, RhinoSubd& out) {
  const std::string who = "vertex " + std::to_string(index);
  read_component_base(reader, who, vertices.begin + static_cast<std::uint32_t>(index));
  const std::uint8_t tag = reader.u8();
  if (tag >= kVertexTagIsCorner.size()) refuse(reader, who + " has unknown tag " + std::to_string(tag));
  if (kVertexTagIsCorner[tag]) out.net.corner_points.push_back(index);
  out.net.points.push_back(reader.point3());
  reader.u16();  // edge count, said again by the edge list
  const std::uint16_t face_count = reader.u16();
  // Cached limit points, one per sector (at most one per face): position, two tangents, normal, face.
  const std::uint8_t mark = reader.u8();
  if (mark != 0) {
    const std::uint32_t count = reader.u32();
    if (count == 0 || count > face_count)
      refuse(reader,
             who + " has " + std::to_string(count) + " limit points for " + std::to_string(face_count) + " faces");
    for (std::uint32_t k = 0; k < count; ++k) {
      const Eigen::Vector3d position = reader.point3();
      reader.skip(2 * 3 * 8);  // tangents
      const Eigen::Vector3d normal = reader.point3();
      read_reference(reader);  // the sector's face
      if (k == 0 && mark == kLimitPointMark) out.limit_points.push_back({index, position, normal});
    }
  }
  skip_references(reader);  // edges
  skip_references(reader);  // faces
  finish_component(reader, who);
}

// Returns the edge's two vertex indices; a crease edge goes into the net too.
std::array<int, 2> read_edge(ArchiveReader& reader, const IdRange& vertices, const IdRange& edges, int index,
                             SubdControlNet& net) {
  const std::string who = "edge " + std::to_string(index);
  read_component_base(reader, who, edges.begin + static_cast<std::uint32_t>(index));
  const std::uint8_t tag = reader.u8();
  if (tag >= kEdgeTags.size() || !kEdgeTags[tag].valid) refuse(reader, who + " has unknown tag " + std::to_string(tag));
  reader.u16();        // face count, said again by the face list
  reader.skip(3 * 8);  // two sector coefficients (Rhino recomputes them) and a sharpness (0 before 80)
  const std::uint16_t ends = reader.u16();
  if (ends != 2) refuse(reader, who + " has " + std::to_string(ends) + " vertices, not 2");
  std::array<int, 2> vertex{};
  for (int& v : vertex) v = vertices.index_of(reader, who, read_reference(reader).archive_id);
  skip_references(reader);  // faces
  finish_component(reader, who);
  if (kEdgeTags[tag].crease) net.crease_edges.push_back(vertex);
  return vertex;
}

// The face's points: each edge's start as the face runs along it (flag bit 0: from its second vertex).
void read_face(ArchiveReader& reader, const IdRange& edges, const std::vector<std::array<int, 2>>& edge_vertices,
               int index, SubdControlNet& net) {
  const std::string who = "face " + std::to_string(index);
  read_component_base(reader, who, edges.end + static_cast<std::uint32_t>(index));
  reader.skip(2 * 4);  // the level-0 face id and an obsolete parent id
  const std::uint16_t edge_count = reader.u16();
  const std::uint16_t listed = reader.u16();
  if (listed != edge_count)
    refuse(reader, who + " lists " + std::to_string(listed) + " edges, its count is " + std::to_string(edge_count));
  std::vector<std::array<int, 2>> sides(edge_count);
  for (auto& side : sides) {
    const Reference ref = read_reference(reader);
    side = edge_vertices[static_cast<std::size_t>(edges.index_of(reader, who, ref.archive_id))];
    if (ref.flags & 1) std::swap(side[0], side[1]);
  }
  finish_component(reader, who);
  std::vector<int> points;
  points.reserve(sides.size());
  for (std::size_t k = 0; k < sides.size(); ++k) {
    if (sides[k][1] != sides[(k + 1) % sides.size()][0])
      refuse(reader, who + ": edge " + std::to_string(k) + " ends at vertex " + std::to_string(sides[k][1]) +
                         ", the next starts at vertex " + std::to_string(sides[(k + 1) % sides.size()][0]));
    points.push_back(sides[k][0]);
  }
  net.faces.push_back(std::move(points));
}

// Level 0's chunk, from the reader's offset to after its end.
RhinoSubd read_level_zero(ArchiveReader& reader) {
  const int major = reader.begin_versioned_chunk(tcode::kAnonymousChunk).first;
  if (major != 1) refuse(reader, "level chunk version " + std::to_string(major) + " (only 1.x is read)");
  const std::uint16_t level = reader.u16();
  if (level != 0) refuse(reader, "first level is level " + std::to_string(level) + ", expected 0");
  reader.skip(3 + 6 * 8);  // subdivision scheme bytes (4 4 4) and the control net's bounding box
  std::array<std::uint32_t, 4> bounds{};
  for (auto& b : bounds) b = reader.u32();
  if (!(bounds[0] <= bounds[1] && bounds[1] <= bounds[2] && bounds[2] <= bounds[3]))
    refuse(reader, "archive id bounds " + std::to_string(bounds[0]) + " " + std::to_string(bounds[1]) + " " +
                       std::to_string(bounds[2]) + " " + std::to_string(bounds[3]) + " do not increase");
  const IdRange vertices{"vertex", bounds[0], bounds[1]}, edges{"edge", bounds[1], bounds[2]};
  const std::uint64_t components = std::uint64_t{bounds[3]} - bounds[0];
  if (components > reader.bytes_left() / kMinComponentBytes)
    refuse(reader, std::to_string(components) + " components cannot fit in the " + std::to_string(reader.bytes_left()) +
                       " bytes left");

  RhinoSubd out;
  out.net.points.reserve(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) read_vertex(reader, vertices, static_cast<int>(v), out);
  std::vector<std::array<int, 2>> edge_vertices(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    edge_vertices[e] = read_edge(reader, vertices, edges, static_cast<int>(e), out.net);
  out.net.faces.reserve(bounds[3] - bounds[2]);
  for (std::uint32_t f = 0; f < bounds[3] - bounds[2]; ++f)
    read_face(reader, edges, edge_vertices, static_cast<int>(f), out.net);
  reader.end_chunk();  // the cached-mesh flag byte (always 0: openNURBS writes no mesh here)
  return out;
}

}  // namespace

RhinoSubd read_subd(ArchiveReader& reader) {
  const int version = reader.archive_version();
  if (version != 60 && version != 70)
    refuse(reader, "archive version " + std::to_string(version) + " is not read (only 60 and 70)");
  const std::uint8_t present = reader.u8();
  if (present == 0) return {};
  if (present != 1) refuse(reader, "first byte " + std::to_string(present) + " is neither 0 nor 1");
  const int major = reader.begin_versioned_chunk(tcode::kAnonymousChunk).first;
  if (major != 1) refuse(reader, "chunk version " + std::to_string(major) + " (only 1.x is read)");
  const std::uint32_t level_count = reader.u32();
  reader.skip(3 * 4 + 6 * 8);  // the largest vertex, edge and face ids, an unused bounding box
  RhinoSubd out;
  if (level_count > 0) out = read_level_zero(reader);
  reader.end_chunk();  // finer levels, texture and symmetry settings
  try {
    validate(out.net, "ON_SubD");
  } catch (const GeometryError& e) {
    refuse(reader, e.reason());
  }
  return out;
}

}  // namespace cadnurbs::rhino
