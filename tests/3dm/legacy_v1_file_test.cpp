// Rhino 1's legacy geometry (version 1 files): the corpus file v1_five_solids.3dm, written by Rhino 1,
// read into RhinoBreps. Expected counts are what the file's own records say (its loop and trim records,
// its glue tables), listed by an independent dump of its chunks; the messages of broken files are built
// from the offsets of the chunks found in the file.
#include <gtest/gtest.h>

#include <cstring>

#include "formats/3dm/legacy_objects.hpp"
#include "formats/3dm/rhino_file.hpp"
#include "formats/3dm/typecodes.hpp"
#include "formats/common/file_io.hpp"
#include "tests/brep/closed_solid.hpp"

namespace cadnurbs::rhino {
namespace {

const std::string kFile = CADNURBS_SHARED_DIR "/corpus/3dm/v1_five_solids.3dm";
constexpr std::size_t kStartSection = 32;

// The file's top-level chunks, in order.
std::vector<ChunkHeader> top_level_chunks(const std::string& bytes) {
  std::vector<ChunkHeader> out;
  ArchiveReader reader(bytes, "v1", 1, kStartSection);
  while (reader.bytes_left() > 0) {
    out.push_back(reader.begin_chunk());
    if (!out.back().is_short()) reader.end_chunk();
  }
  return out;
}

// Per face: its trims per loop.
std::vector<std::vector<int>> trims_per_loop(const RhinoBrep& brep) {
  std::vector<std::vector<int>> out;
  for (const auto& face : brep.faces) {
    out.emplace_back();
    for (const auto& loop : face.loops) out.back().push_back(static_cast<int>(loop.segments.size()));
  }
  return out;
}

TEST(LegacyV1File, FiveSolidsAreReadAsBrepsWithTheFilesLoopsTrimsAndEdges) {
  const Rhino3dmFile file = read_3dm_file(kFile);
  EXPECT_EQ(file.archive_version, 1);
  EXPECT_EQ(file.warnings, std::vector<std::string>{"the model has no unit system; millimetres assumed"});
  EXPECT_DOUBLE_EQ(file.absolute_tolerance, 0.01);
  ASSERT_EQ(file.layers.size(), 1u);
  EXPECT_EQ(file.layers[0].name, "Default");
  ASSERT_EQ(file.objects.size(), 5u);

  // A box, a cylinder and a cone (shells: 6, 3 and 2 faces), a torus and a sphere (faces); one loop per
  // face; a cap's loop is one trim (its circle), every other loop four.
  const std::vector<std::vector<std::vector<int>>> loops = {
      {{4}, {4}, {4}, {4}, {4}, {4}}, {{4}, {1}, {1}}, {{4}, {1}}, {{4}}, {{4}}};
  // Edges: the box's 12; the cylinder's seam and two circles; the cone's seam and base circle; the
  // torus's two seams; the sphere's seam (its poles are singular trims, on no edge).
  const std::vector<int> edges = {12, 3, 2, 2, 1};
  for (std::size_t i = 0; i < file.objects.size(); ++i) {
    SCOPED_TRACE("object " + std::to_string(i));
    const ObjectRecord& object = file.objects[i];
    EXPECT_EQ(object.index, static_cast<int>(i));
    EXPECT_EQ(object.class_name, "ON_Brep");
    EXPECT_EQ(object.attributes.layer_index, 0);
    const auto* brep = std::get_if<RhinoBrep>(&object.geometry);
    ASSERT_NE(brep, nullptr);
    EXPECT_TRUE(brep->skipped_faces.empty());
    EXPECT_EQ(trims_per_loop(*brep), loops[i]);
    EXPECT_EQ(brep->edge_count, edges[i]);
    EXPECT_TRUE(brep->render_meshes.empty());  // Rhino 1 stores no meshes with its surfaces

    // Closed: every edge is used by two trims, once each way (closed_solid's test on a scene node).
    SceneNode node;
    for (const auto& face : brep->faces) node.shapes.push_back(Shape{"", face, std::nullopt, "Brep face"});
    EXPECT_TRUE(test::closed_solid(node));
  }
}

TEST(LegacyV1File, ATruncatedLegacyChunkIsRefusedNamingItsTypecodeAndOffset) {
  const std::string bytes = read_file(kFile);
  const std::vector<ChunkHeader> chunks = top_level_chunks(bytes);
  ASSERT_EQ(chunks.back().typecode, tcode::kLegacyFace);
  const ChunkHeader& last = chunks.back();
  const std::string cut = bytes.substr(0, last.body_begin + 100);
  try {
    parse_3dm(cut, "cut.3dm");
    FAIL() << "no error";
  } catch (const ArchiveError& e) {
    EXPECT_EQ(std::string(e.what()), "cut.3dm: chunk 0x00010004 at offset " + std::to_string(last.offset) +
                                         ": length " + std::to_string(last.value) +
                                         " runs past the end of the file (100 bytes left)");
  }
}

TEST(LegacyV1File, AShellWhoseFaceCountDoesNotFitIsSkippedWithAWarningAndTheRestIsRead) {
  std::string bytes = read_file(kFile);
  const std::vector<ChunkHeader> chunks = top_level_chunks(bytes);
  // The first shell's stuff chunk, after its attribute chunks.
  std::size_t shell = 0;
  for (const auto& h : chunks)
    if (h.typecode == tcode::kLegacyShell) {
      shell = h.offset;
      break;
    }
  ArchiveReader walk(bytes, "v1", 1, shell);
  walk.begin_chunk(tcode::kLegacyShell);
  ChunkHeader stuff;
  do {
    stuff = walk.begin_chunk();
    if (!stuff.is_short() && stuff.typecode != tcode::kLegacyShellStuff) walk.end_chunk();
  } while (stuff.typecode != tcode::kLegacyShellStuff);
  const std::int32_t faces = 2000;                              // 2000 chunk headers need 16000 bytes
  std::memcpy(bytes.data() + stuff.body_begin + 4, &faces, 4);  // outer flag, then the face count
  const std::int32_t glue = 24;                                 // the box's glue count, as the file has it
  const std::size_t after_glue = stuff.body_begin + 4 + 4 + 48 + 4 + 2 * glue;

  const Rhino3dmFile file = parse_3dm(bytes, "x.3dm");
  ASSERT_EQ(file.objects.size(), 5u);
  EXPECT_TRUE(std::holds_alternative<Unsupported>(file.objects[0].geometry));
  for (std::size_t i = 1; i < 5; ++i) EXPECT_TRUE(std::holds_alternative<RhinoBrep>(file.objects[i].geometry));
  ASSERT_EQ(file.warnings.size(), 2u);  // the units' (the units chunk comes first), then the shell's
  EXPECT_EQ(file.warnings[1], "object 0 (ON_Brep): x.3dm: chunk 0x00010103 at offset " + std::to_string(stuff.offset) +
                                  ": legacy shell: 2000 faces cannot fit in the " +
                                  std::to_string(stuff.body_end - after_glue) + " bytes left; skipped");
}

TEST(LegacyV1File, ObjectChunksAreKnownByTheirTypecode) {
  EXPECT_EQ(v1_object_class(tcode::kLegacyShell), "ON_Brep");
  EXPECT_EQ(v1_object_class(tcode::kLegacyFace), "ON_Brep");
  EXPECT_EQ(v1_object_class(tcode::kLegacyCurve), "ON_NurbsCurve");
  EXPECT_EQ(v1_object_class(tcode::kMeshObject), "ON_Mesh");  // read as openNURBS reads it
  EXPECT_EQ(v1_object_class(tcode::kRhPoint), "V1 point");
  EXPECT_EQ(v1_object_class(tcode::kV1Layer), "");
}

}  // namespace
}  // namespace cadnurbs::rhino
