// Whole .3dm files written by Rhino (the shared corpus): version, unit, tolerance, layers, object classes,
// names, layers and colours. Expected values are what McNeel's rhino3dm 8 (npm, OpenNURBS) reads from the
// same files, and the corpus MANIFEST's object classes.
#include "formats/3dm/rhino_file.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "class_chunks.hpp"
#include "formats/3dm/typecodes.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs::rhino {
namespace {

std::string corpus(const std::string& file) { return CADNURBS_SHARED_DIR "/corpus/3dm/" + file; }

std::vector<std::string> classes_of(const Rhino3dmFile& f) {
  std::vector<std::string> out;
  for (const auto& o : f.objects) out.push_back(o.class_name);
  return out;
}

std::vector<std::string> layer_names(const Rhino3dmFile& f) {
  std::vector<std::string> out;
  for (const auto& l : f.layers) out.push_back(l.name);
  return out;
}

std::vector<std::string> repeated(const std::string& s, int n) { return std::vector<std::string>(static_cast<std::size_t>(n), s); }

struct Expected {
  const char* file;
  int version;
  double tolerance;
  std::vector<std::string> classes;
  std::vector<std::string> layers;
};

TEST(RhinoFile, CorpusFilesHaveTheirVersionUnitLayersAndObjectClasses) {
  const std::string nc = "ON_NurbsCurve", ac = "ON_ArcCurve", pl = "ON_PolylineCurve", ex = "ON_Extrusion";
  const std::vector<Expected> files = {
      {"mesh.3dm", 80, 0.001, {"ON_Mesh"}, {"Default"}},
      {"v2_my_trimmed_surface.3dm", 2, 0.01, {"ON_Brep"}, {"Default"}},
      {"v4_MechPartA.3dm", 4, 0.001, {"ON_Brep"}, {"Default"}},
      {"v5_extrusions.3dm", 50, 0.001, {pl, ac, nc, nc, ac, ac, ex, ex, ex, ex, nc, nc, pl, nc, ex, ex, ex}, {"Default", "Curves"}},
      {"v5_teapot.3dm", 50, 0.01, repeated("ON_Brep", 3), {"Lids", "Logos", "Pots"}},
      {"v6_rhino_subd_logo.3dm", 60, 0.01, {"ON_Mesh", "ON_Mesh", "ON_Mesh", "ON_Mesh", "ON_Mesh", "ON_Mesh", "ON_SubD",
        "ON_SubD", "ON_SubD", "ON_SubD", "ON_SubD", "ON_SubD"}, {"Default", "SubD", "SUbDFromMesh Net"}},
      {"v7_my_brep.3dm", 70, 0.001, {"ON_Brep"}, {"brep"}},
      {"v7_my_surfaces.3dm", 70, 0.001, {"ON_NurbsSurface"}, {"Default"}},
      {"v7_rhino_logo_nurbs.3dm", 70, 0.01, repeated("ON_Brep", 6), {"Rhino Logo"}},
      {"v7_rhino_logo_subd.3dm", 70, 0.01, repeated("ON_SubD", 6), {"Rhino Logo"}},
  };
  for (const Expected& e : files) {
    SCOPED_TRACE(e.file);
    const Rhino3dmFile f = read_3dm_file(corpus(e.file));
    EXPECT_EQ(f.archive_version, e.version);
    EXPECT_EQ(f.unit.name, "mm");
    EXPECT_EQ(f.unit.millimetres, 1.0);
    EXPECT_EQ(f.absolute_tolerance, e.tolerance);
    EXPECT_EQ(classes_of(f), e.classes);
    EXPECT_EQ(layer_names(f), e.layers);
    for (std::size_t i = 0; i < f.objects.size(); ++i) EXPECT_EQ(f.objects[i].index, static_cast<int>(i));
  }
}

TEST(RhinoFile, SubdObjectsAndMeshesAreRead) {
  const Rhino3dmFile f = read_3dm_file(corpus("v6_rhino_subd_logo.3dm"));
  ASSERT_EQ(f.objects.size(), 12u);
  for (int i = 0; i < 6; ++i) EXPECT_TRUE(std::holds_alternative<TriangleMesh>(f.objects[static_cast<std::size_t>(i)].geometry)) << i;
  for (int i = 6; i < 12; ++i) EXPECT_TRUE(std::holds_alternative<RhinoSubd>(f.objects[static_cast<std::size_t>(i)].geometry)) << i;
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_EQ(std::get<TriangleMesh>(f.objects[0].geometry).positions.size(), 174u);
}

TEST(RhinoFile, ObjectNamesLayersAndColoursFromTheAttributes) {
  const Rhino3dmFile brep = read_3dm_file(corpus("v7_my_brep.3dm"));
  ASSERT_EQ(brep.objects.size(), 1u);
  EXPECT_EQ(brep.objects[0].attributes.name, "Twisted b-rep");
  EXPECT_EQ(brep.objects[0].attributes.layer_index, 0);
  EXPECT_FALSE(brep.objects[0].attributes.colour);

  const Rhino3dmFile teapot = read_3dm_file(corpus("v5_teapot.3dm"));
  ASSERT_EQ(teapot.objects.size(), 3u);
  EXPECT_EQ(teapot.objects[0].attributes.layer_index, 2);
  EXPECT_EQ(teapot.objects[1].attributes.layer_index, 0);
  EXPECT_EQ(teapot.objects[2].attributes.layer_index, 1);
  EXPECT_EQ(teapot.layers[0].colour, (Colour{191 / 255.0, 63 / 255.0, 63 / 255.0}));
  EXPECT_EQ(teapot.layers[2].colour, (Colour{53 / 255.0, 53 / 255.0, 117 / 255.0}));

  const Rhino3dmFile subd = read_3dm_file(corpus("v6_rhino_subd_logo.3dm"));
  for (const auto& o : subd.objects) {
    SCOPED_TRACE(o.index);
    EXPECT_EQ(o.attributes.layer_index, o.index < 6 ? 2 : 1);
    if (o.index == 10) EXPECT_EQ(o.attributes.colour, (Colour{1, 0, 0}));  // colour from object: red
    else EXPECT_FALSE(o.attributes.colour);
  }
  const Rhino3dmFile logo = read_3dm_file(corpus("v7_rhino_logo_nurbs.3dm"));
  ASSERT_EQ(logo.objects.size(), 6u);
  EXPECT_EQ(logo.objects[5].attributes.colour, (Colour{1, 0, 0}));
  EXPECT_FALSE(logo.objects[4].attributes.colour);
  EXPECT_EQ(read_3dm_file(corpus("v7_my_surfaces.3dm")).objects[0].attributes.layer_index, -1);
}

TEST(RhinoFile, StartSectionAndVersionAreChecked) {
  const auto error = [](const std::string& bytes) {
    try {
      parse_3dm(bytes, "x.3dm");
    } catch (const ArchiveError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("hello"), "x.3dm: offset 0: not a .3dm file (no \"3D Geometry File Format\" start section)");
  EXPECT_EQ(error("3D Geometry File Format       90"),
            "x.3dm: offset 24: archive version \"      90\" is not one cadnurbs reads (1-5, 50, 60, 70, 80)");
  EXPECT_EQ(error("3D Geometry File Format       7x"),
            "x.3dm: offset 24: archive version \"      7x\" is not one cadnurbs reads (1-5, 50, 60, 70, 80)");
}

// The top-level chunk whose body a cut at `size` bytes falls into, found by walking the headers directly.
std::pair<std::uint32_t, std::size_t> chunk_cut_by(const std::string& bytes, std::size_t size) {
  std::size_t at = 32;
  for (;;) {
    std::uint32_t typecode;
    std::int64_t length;
    std::memcpy(&typecode, bytes.data() + at, 4);
    std::memcpy(&length, bytes.data() + at + 4, 8);
    const std::size_t end = at + 12 + ((typecode & tcode::kShort) ? 0 : static_cast<std::size_t>(length));
    if (end > size) return {typecode, at};
    at = end;
  }
}

TEST(RhinoFile, TruncatedFileGivesOneLineNamingChunkAndOffset) {
  const std::string bytes = read_file(corpus("v7_my_brep.3dm"));
  const std::string cut = bytes.substr(0, bytes.size() * 2 / 3);
  const auto [typecode, offset] = chunk_cut_by(bytes, cut.size());
  std::int64_t length;
  std::memcpy(&length, bytes.data() + offset + 4, 8);
  char expected[200];
  std::snprintf(expected, sizeof expected,
                "cut.3dm: chunk 0x%08X at offset %zu: length %lld runs past the end of the file (%zu bytes left)", typecode,
                offset, static_cast<long long>(length), cut.size() - offset - 12);
  try {
    parse_3dm(cut, "cut.3dm");
    FAIL() << "no error";
  } catch (const ArchiveError& e) {
    EXPECT_STREQ(e.what(), expected);
  }
  EXPECT_EQ(typecode, tcode::kObjectTable);  // two thirds into this file is its one Brep
}

TEST(RhinoFile, AnObjectThatFailsToReadIsSkippedAndTheNextOnesRead) {
  std::string bytes = read_file(corpus("v6_rhino_subd_logo.3dm"));
  const auto meshes = testing::class_chunk_offsets(bytes, "4ED7D4E4-E947-11D3-BFE5-0010830122F0");
  ASSERT_EQ(meshes.size(), 6u);
  // Mesh 1's class data starts after the class chunk's header (12 bytes), its uuid chunk (12 + 16 + 4)
  // and the data chunk's header (12): make its chunk version 9.0, which the mesh reader refuses.
  const std::size_t version_byte = meshes[1] + 12 + 32 + 12;
  ASSERT_EQ(static_cast<unsigned char>(bytes[version_byte]) >> 4, 3);  // ON_Mesh chunk version 3.x
  bytes[version_byte] = static_cast<char>(0x90);
  const Rhino3dmFile f = parse_3dm(bytes, "bad.3dm");
  ASSERT_EQ(f.objects.size(), 12u);
  EXPECT_EQ(f.objects[1].class_name, "ON_Mesh");
  ASSERT_TRUE(std::holds_alternative<Unsupported>(f.objects[1].geometry));
  for (int i : {0, 2, 3, 4, 5}) EXPECT_TRUE(std::holds_alternative<TriangleMesh>(f.objects[static_cast<std::size_t>(i)].geometry)) << i;
  char expected[200];
  std::snprintf(expected, sizeof expected,
                "object 1 (ON_Mesh): bad.3dm: chunk 0x0002FFFC at offset %zu: ON_Mesh: chunk version 9.0 is not 1.x or 3.x; "
                "skipped",
                meshes[1] + 44);
  ASSERT_EQ(f.warnings.size(), 1u);  // that one
  EXPECT_EQ(f.warnings[0], expected);
}

TEST(RhinoFile, ALayerThatFailsToReadKeepsItsPlace) {
  std::string bytes = read_file(corpus("v5_teapot.3dm"));
  const auto layers = testing::class_chunk_offsets(bytes, "95809813-E985-11D3-BFE5-0010830122F0");  // ON_Layer
  ASSERT_EQ(layers.size(), 3u);
  bytes[layers[1] + 12 + 32 + 12] = static_cast<char>(0x70);  // layer chunk version 7.0
  const Rhino3dmFile f = parse_3dm(bytes, "layer.3dm");
  EXPECT_EQ(layer_names(f), (std::vector<std::string>{"Lids", "layer 1", "Pots"}));
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_EQ(f.warnings[0], "layer 1: layer.3dm: chunk 0x0002FFFC at offset " + std::to_string(layers[1] + 44) +
                               ": ON_Layer: chunk version 7.0 is not 1.x; named \"layer 1\"");
  EXPECT_EQ(f.objects.size(), 3u);
  EXPECT_EQ(f.objects[2].attributes.layer_index, 1);
}

TEST(RhinoFile, ACorruptedByteUnderACrcIsCaught) {
  std::string bytes = read_file(corpus("mesh.3dm"));
  const auto meshes = testing::class_chunk_offsets(bytes, "4ED7D4E4-E947-11D3-BFE5-0010830122F0");
  ASSERT_EQ(meshes.size(), 1u);
  // The last byte of the class id inside the TCODE_OPENNURBS_CLASS_UUID chunk (CRC-checked, read whole).
  const std::size_t uuid_chunk = meshes[0] + 12;
  bytes[uuid_chunk + 12 + 15] ^= 0x01;
  const Rhino3dmFile f = parse_3dm(bytes, "crc.3dm");
  ASSERT_EQ(f.objects.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Unsupported>(f.objects[0].geometry));
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("crc.3dm: chunk 0x0002FFFB at offset " + std::to_string(uuid_chunk) + ": CRC mismatch"),
            std::string::npos)
      << f.warnings[0];
}

}  // namespace
}  // namespace cadnurbs::rhino
