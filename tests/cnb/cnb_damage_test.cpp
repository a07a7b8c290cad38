// Damaged and truncated .cnb files: each refused with one FileError line naming the file, the byte and
// what is wrong; payloads that claim more than their bytes can hold refused before allocating.
#include <gtest/gtest.h>

#include "formats/cnb/cnb_container.hpp"
#include "formats/cnb/cnb_numbers.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/common/file_io.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "tests/cnb/cnb_file_header.hpp"

namespace cadnurbs {
namespace {

const std::string name = "capping-90.cnb";

const std::string& capping_file() {
  static const std::string bytes = [] {
    CnbOptions options;
    options.max_deviation = 0.01;
    return write_cnb(read_vrml(std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-90.x3dv"), options);
  }();
  return bytes;
}

std::string error_of(const std::string& bytes) { return read_error(bytes, name); }

TEST(CnbDamage, TruncatedFiles) {
  const std::string& file = capping_file();
  const size_t crc_at = crc_offset(file);
  EXPECT_EQ(error_of(""), name + ": byte 0: truncated: the file ends inside the magic number");
  EXPECT_EQ(error_of(file.substr(0, 2)), name + ": byte 2: truncated: the file ends inside the magic number");
  for (size_t cut : {size_t(5), size_t(7), crc_at + 2})
    EXPECT_EQ(error_of(file.substr(0, cut)), name + ": byte " + std::to_string(cut) + ": truncated: the file ends inside the header");
  for (size_t cut : {crc_at + 4, crc_at + 5, file.size() / 2, file.size() - 1})
    EXPECT_EQ(error_of(file.substr(0, cut)), name + ": byte " + std::to_string(crc_at) +
                                                 ": damaged or truncated: the CRC-32 of the file does not match the one in its header");
  EXPECT_EQ(error_of(file + "x"), name + ": byte " + std::to_string(crc_at) +
                                      ": damaged or truncated: the CRC-32 of the file does not match the one in its header");
}

// Every byte of the file flipped in turn gives the message for the field it lies in: the magic number,
// the version, and past them the CRC-32 (which covers the rest of the header and the coded bytes).
TEST(CnbDamage, EveryFlippedByteIsRefused) {
  const std::string& file = capping_file();
  const std::string crc_message = name + ": byte " + std::to_string(crc_offset(file)) +
                                  ": damaged or truncated: the CRC-32 of the file does not match the one in its header";
  for (size_t at = 0; at < file.size(); ++at) {
    std::string damaged = file;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x24);
    std::string expected;
    if (at < 4) expected = name + ": byte " + std::to_string(at) + ": not a .cnb file (the magic number is \\x89CNB)";
    else if (at == 4) expected = name + ": byte 4: version " + std::to_string(cnb::format_version ^ 0x24) +
                            " is not one this reader knows (1 to " + std::to_string(cnb::format_version) + ")";
    else expected = crc_message;
    ASSERT_EQ(error_of(damaged), expected) << "byte " << at;
  }
}

TEST(CnbDamage, HeaderClaimingAnImpossiblePayloadSize) {
  CnbOptions options;
  options.coder = CnbOptions::Coder::deflate;
  const std::string file = write_cnb(read_vrml(std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-end.x3dv"), options);
  const std::string huge = with_payload_size(file, 0xFFFFFFFFu);
  const size_t coded = huge.size() - crc_offset(huge) - 4;
  EXPECT_EQ(error_of(huge), name + ": byte 6: a payload of 4294967295 bytes cannot come from " + std::to_string(coded) +
                                " deflated bytes");
  EXPECT_EQ(error_of(with_payload_size(file, uint64_t(1) << 33)), name + ": byte 6: damaged: a payload size above 4 GiB");
  // One byte fewer than the stream holds.
  const uint64_t size = payload_size(file) - 1;
  EXPECT_EQ(error_of(with_payload_size(file, size)),
            name + ": byte 6: the deflate stream holds more than the " + std::to_string(size) + " payload bytes the header promises");
}

// A file of format version 1 (an 18-byte header with the coded size, float64 numbers in the scene
// header), as earlier writers made them, still reads: one triangle.
TEST(CnbDamage, VersionOneFilesStillRead) {
  cnb::ByteWriter w;
  w.text("mm");
  w.float64(1.0);
  w.text("in");
  w.float64(25.4);
  for (double v : {0.1, 0.1, 0.0866}) w.float64(v);  // D, q, bound
  w.text("part");
  w.byte(0);                        // node flags
  w.varuint(1, cnb::Field::count);  // one shape
  w.byte(2);                        // a triangle mesh
  w.text("t");
  w.varuint(3, cnb::Field::count);
  for (int c : {0, 0, 0, 10, 0, 0, -10, 10, 0}) w.varsint(c, cnb::Field::point);  // (0,0,0) (1,0,0) (0,1,0)
  w.varuint(1, cnb::Field::count);
  for (int d : {0, 1, 1}) w.varsint(d, cnb::Field::index);
  w.byte(0);                        // no normals
  w.varuint(0, cnb::Field::count);  // no children
  std::string deflated(compressBound(static_cast<uLong>(w.bytes().size())) + 16, '\0');
  z_stream z{};
  ASSERT_EQ(deflateInit2(&z, 9, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY), Z_OK);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(w.bytes().data()));
  z.avail_in = static_cast<uInt>(w.bytes().size());
  z.next_out = reinterpret_cast<Bytef*>(deflated.data());
  z.avail_out = static_cast<uInt>(deflated.size());
  ASSERT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  deflated.resize(z.total_out);
  deflateEnd(&z);
  std::string file = std::string("\x89" "CNB", 4) + '\x01' + '\x01';
  for (uint32_t v : {static_cast<uint32_t>(w.bytes().size()), static_cast<uint32_t>(deflated.size())})
    for (int i = 0; i < 4; ++i) file.push_back(static_cast<char>(v >> (8 * i)));
  uLong c = crc32(0L, reinterpret_cast<const Bytef*>(file.data()), 14);
  c = crc32(c, reinterpret_cast<const Bytef*>(deflated.data()), static_cast<uInt>(deflated.size()));
  for (int i = 0; i < 4; ++i) file.push_back(static_cast<char>(c >> (8 * i)));
  file += deflated;
  const Scene scene = read_cnb(file, name);
  EXPECT_EQ(scene.source_unit.name, "in");
  EXPECT_EQ(scene.source_unit.millimetres, 25.4);
  ASSERT_EQ(scene.root.shapes.size(), 1u);
  const auto& mesh = std::get<TriangleMesh>(scene.root.shapes[0].geometry);
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.positions[1], Eigen::Vector3d(1.0, 0, 0));
  EXPECT_EQ(mesh.positions[2], Eigen::Vector3d(0, 1.0, 0));
  EXPECT_EQ(mesh.triangles.at(0), (std::array<int, 3>{0, 1, 2}));
}

// A payload's scene header (unit mm, D = q = bound = 1; version 3: sizes, D and the bound as exact
// numbers, q as a float32) and the root node's name and flags.
cnb::ByteWriter scene_header_and_root(uint8_t root_flags = 0) {
  cnb::ByteWriter w;
  w.text("mm");
  cnb::write_exact_number(w, 1.0);
  w.text("mm");
  cnb::write_exact_number(w, 1.0);
  cnb::write_exact_number(w, 1.0);
  w.float32(1.0f);
  cnb::write_exact_number(w, 1.0);
  w.text("");
  w.byte(root_flags);
  return w;
}

// A file of format version 2 (the grid step and the bound as raw float64), as writers made them before
// version 3, still reads: one triangle, on the grid its float64 step gives.
TEST(CnbDamage, VersionTwoFilesStillRead) {
  cnb::ByteWriter w;
  w.text("mm");
  cnb::write_exact_number(w, 1.0);
  w.text("mm");
  cnb::write_exact_number(w, 1.0);
  cnb::write_exact_number(w, 0.1);  // D
  w.float64(0.0866);                // q
  w.float64(0.075);                 // the bound
  w.text("");
  w.byte(0);
  w.varuint(1, cnb::Field::count);  // one shape
  w.byte(2);                        // a triangle mesh
  w.text("t");
  w.varuint(3, cnb::Field::count);
  for (int c : {0, 0, 0, 10, 0, 0, -10, 10, 0}) w.varsint(c, cnb::Field::point);
  w.varuint(1, cnb::Field::count);
  for (int d : {0, 1, 1}) w.varsint(d, cnb::Field::index);
  w.byte(0);                        // no normals
  w.varuint(0, cnb::Field::count);  // no children
  std::string file = cnb::pack(w, CnbOptions::Coder::deflate, nullptr);
  file = with_version(file, 2);
  const Scene scene = read_cnb(file, name);
  const auto& mesh = std::get<TriangleMesh>(scene.root.shapes.at(0).geometry);
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.positions[1], Eigen::Vector3d(10 * 0.0866, 0, 0));
}

// A payload with a valid checksum whose counts lie: refused at the count, before allocating.
TEST(CnbDamage, CountsBeyondTheBytesLeft) {
  for (auto coder : {CnbOptions::Coder::deflate, CnbOptions::Coder::arithmetic}) {
    cnb::ByteWriter w = scene_header_and_root();
    const size_t count_at = w.bytes().size();
    w.varuint(1000000, cnb::Field::count);  // shapes
    w.varuint(0, cnb::Field::count);        // children
    const std::string file = cnb::pack(w, coder, nullptr);
    EXPECT_EQ(error_of(file), name + ": decoded byte " + std::to_string(count_at) +
                                  ": count 1000000 cannot fit in the 1 bytes left");
  }
}

// A surface whose knot multiplicities do not add up to what its net needs.
TEST(CnbDamage, KnotsThatDoNotFitTheNet) {
  cnb::ByteWriter w = scene_header_and_root();
  w.varuint(1, cnb::Field::count);  // one shape
  w.byte(0);                        // a trimmed surface
  w.text("face");
  for (int v : {2, 2, 2, 2}) w.varuint(v, cnb::Field::count);  // orders, counts
  const size_t knots_at = w.bytes().size();
  w.varuint(2, cnb::Field::count);  // two distinct knots
  w.byte(0, cnb::Field::knot);      // whole numbers
  w.varsint(0, cnb::Field::knot);
  w.varuint(0, cnb::Field::knot);
  w.varuint(1, cnb::Field::count);  // multiplicity 2
  w.varuint(0, cnb::Field::count);  // multiplicity 1: 3 knots where 4 are needed
  for (int i = 0; i < 40; ++i) w.byte(0);
  EXPECT_EQ(error_of(cnb::pack(w, CnbOptions::Coder::deflate, nullptr)),
            name + ": decoded byte " + std::to_string(knots_at) + ": knot multiplicities add up to 3, the net needs 4");
}

// Repeats of a large shape: refused once the scene would hold more numbers than the payload allows.
TEST(CnbDamage, RepeatsBeyondTheNumberBudget) {
  cnb::ByteWriter w = scene_header_and_root();
  const int vertices = 1000, repeats = 2000;
  w.varuint(1 + repeats, cnb::Field::count);  // shapes
  w.byte(2);                                  // a triangle mesh
  w.text("");
  w.varuint(vertices, cnb::Field::count);
  for (int i = 0; i < 3 * vertices; ++i) w.varsint(0, cnb::Field::point);
  w.varuint(1, cnb::Field::count);
  for (int k = 0; k < 3; ++k) w.varsint(0, cnb::Field::index);
  w.byte(0);  // no normals
  std::vector<size_t> repeat_at;
  for (int r = 0; r < repeats; ++r) {
    w.byte(4);  // the same geometry as the shape just before
    w.text("");
    repeat_at.push_back(w.bytes().size());
    w.varuint(0, cnb::Field::index);
  }
  w.varuint(0, cnb::Field::count);  // children
  const size_t budget = 256 * w.bytes().size() + (size_t(1) << 20), each = 3 * vertices + 3;
  const size_t failing = budget / each;  // shapes that fit: the mesh and failing - 1 repeats
  ASSERT_LT(failing, size_t(repeats));
  EXPECT_EQ(error_of(cnb::pack(w, CnbOptions::Coder::deflate, nullptr)),
            name + ": decoded byte " + std::to_string(repeat_at[failing - 1]) + ": the scene would hold more than " +
                std::to_string(budget) + " numbers (256 per payload byte and 1048576)");
}

// A traversal of one triangle: the vertex count, the triangle count, no period, three new vertices (no axis
// listed, each a difference from the previous).
void one_triangle_traversal(cnb::ByteWriter& w) {
  w.varuint(3, cnb::Field::count);
  w.varuint(1, cnb::Field::count);
  for (int k = 0; k < 3; ++k) w.varsint(0, cnb::Field::point);  // no period; (version 8) no predictors named
  for (int v = 0; v < 3; ++v) {
    w.byte(0);  // symbol: a new vertex
    w.byte(0);  // no axis holds a listed value
    for (int k = 0; k < 3; ++k) w.varsint(k == v ? 1 : 0, cnb::Field::mesh_point);
  }
}

// A mesh group record (shape kind 6) of `names.size()` meshes whose traversal holds one triangle, of the
// first mesh: its member code is 0 (the predicted one, the first mesh).
void one_triangle_group(cnb::ByteWriter& w, const std::vector<std::string>& names) {
  w.byte(6);
  w.varuint(names.size(), cnb::Field::count);
  for (const auto& n : names) {
    w.byte(0);
    w.text(n);
  }
  one_triangle_traversal(w);
  w.byte(0);  // the member: the predicted one
}

// A mesh group must hold 2 to 255 meshes, all among the node's shapes, and each mesh a triangle.
// A version 4 colour naming a place beyond the colours met, or a component beyond its scale.
TEST(CnbDamage, ColoursThatCannotBeRight) {
  const auto error_for = [](std::initializer_list<uint64_t> colour) {
    cnb::ByteWriter w = scene_header_and_root(1);  // the root has a colour
    const size_t at = w.bytes().size();
    for (uint64_t v : colour) w.varuint(v, cnb::Field::raw);
    w.varuint(0, cnb::Field::count);  // no shapes
    w.varuint(0, cnb::Field::count);  // no children
    return std::pair{at, error_of(cnb::pack(w, CnbOptions::Coder::deflate, nullptr))};
  };
  const auto [cached_at, cached] = error_for({3});
  EXPECT_EQ(cached, name + ": decoded byte " + std::to_string(cached_at) + ": colour 1 back, with 0 met");
  const auto [thousandths_at, thousandths] = error_for({1, 500, 1001, 0});
  EXPECT_EQ(thousandths, name + ": decoded byte " + std::to_string(thousandths_at + 3) + ": colour component 1001 above 1000");
  const auto [bytes_at, bytes] = error_for({2, 256, 0, 0});
  EXPECT_EQ(bytes, name + ": decoded byte " + std::to_string(bytes_at + 1) + ": colour component 256 above 255");
}

TEST(CnbDamage, MeshGroupsThatCannotBeRight) {
  // A node of `shapes` shapes whose first record is a group claiming `group` of them.
  auto group_count_error = [](int shapes, int group) {
    cnb::ByteWriter w = scene_header_and_root();
    w.varuint(shapes, cnb::Field::count);
    w.byte(6);
    const size_t count_at = w.bytes().size();
    w.varuint(group, cnb::Field::count);
    for (int i = 0; i < 40; ++i) w.byte(0);
    return std::pair{count_at, error_of(cnb::pack(w, CnbOptions::Coder::deflate, nullptr))};
  };
  {
    const auto [count_at, error] = group_count_error(3, 4);
    EXPECT_EQ(error, name + ": decoded byte " + std::to_string(count_at) +
                         ": a mesh group of 4 shapes (2 to 255, and 3 left in the node)");
  }
  {
    const auto [count_at, error] = group_count_error(1, 1);
    EXPECT_EQ(error, name + ": decoded byte " + std::to_string(count_at) +
                         ": a mesh group of 1 shapes (2 to 255, and 1 left in the node)");
  }
  {
    cnb::ByteWriter w = scene_header_and_root();
    w.varuint(2, cnb::Field::count);
    const size_t group_at = w.bytes().size();
    one_triangle_group(w, {"a", "b"});
    const size_t traversal_at = group_at + 1 + 1 + 2 * 3;  // kind, count, two (flags, name)
    w.varuint(0, cnb::Field::count);  // children
    EXPECT_EQ(error_of(cnb::pack(w, CnbOptions::Coder::deflate, nullptr)),
              name + ": decoded byte " + std::to_string(traversal_at) + ": mesh 2 of a group of 2 has no triangle");
  }
  {  // the same with both meshes named by the one triangle's code: member 2 of a group of 2 does not exist
    cnb::ByteWriter w = scene_header_and_root();
    w.varuint(2, cnb::Field::count);
    one_triangle_group(w, {"a", "b"});
    std::string payload = w.bytes();
    payload.back() = 3;  // member code 3: mesh number 2 (counted from 0)
    cnb::ByteWriter damaged;
    for (char c : payload) damaged.byte(static_cast<uint8_t>(c));
    damaged.varuint(0, cnb::Field::count);
    EXPECT_EQ(error_of(cnb::pack(damaged, CnbOptions::Coder::deflate, nullptr)),
              name + ": decoded byte " + std::to_string(payload.size() - 1) + ": member 2 of a group of 2 meshes");
  }
}

// The root's one shape, a traversal-coded mesh of `vertices` and `triangles` whose period's x is
// `period_x` (its y and z 0), up to its starting triangle: three new vertices (0,0,0) + the unit steps.
void traversal_start(cnb::ByteWriter& w, uint64_t vertices, uint64_t triangles, int64_t period_x) {
  w.varuint(1, cnb::Field::count);  // the node's shapes
  w.byte(5);
  w.text("");
  w.varuint(vertices, cnb::Field::count);
  w.varuint(triangles, cnb::Field::count);
  for (int k = 0; k < 3; ++k) w.varsint(k == 0 ? period_x : 0, cnb::Field::point);
  for (int v = 0; v < 3; ++v) {
    w.byte_in(0, cnb::symbol_context(0));
    w.byte(0, cnb::Field::mesh_axes);
    for (int k = 0; k < 3; ++k) w.varsint_in(k == v ? 1 : 0, cnb::Field::mesh_point, cnb::axis_context(cnb::Field::mesh_point, k));
  }
}

// A new vertex naming a fifth predictor (version 8), in a mesh whose period's x is 2 * 0 + 1: predictors named.
TEST(CnbDamage, VertexPredictorsThatCannotBeRight) {
  // A shape of two triangles: the period's x 1 (predictors named), the starting triangle's three vertices,
  // then a new vertex beyond its first edge that names `predictor`.
  const auto error_for = [](uint8_t predictor) {
    cnb::ByteWriter w = scene_header_and_root();
    traversal_start(w, 4, 2, 1);
    w.byte_in(0, cnb::gate_symbol_context(0));
    const size_t predictor_at = w.bytes().size();
    w.byte_in(predictor, cnb::predictor_context(0));
    w.byte(0, cnb::Field::mesh_axes);
    for (int k = 0; k < 3; ++k) w.varsint_in(0, cnb::Field::mesh_point, cnb::axis_context(cnb::Field::mesh_point, k));
    w.varuint(0, cnb::Field::count);  // children
    return std::pair{predictor_at, error_of(cnb::pack(w, CnbOptions::Coder::deflate, nullptr))};
  };
  {
    const auto [predictor_at, error] = error_for(3);
    EXPECT_EQ(error, "(read without error)");
  }
  {
    const auto [predictor_at, error] = error_for(4);
    EXPECT_EQ(error, name + ": decoded byte " + std::to_string(predictor_at) + ": unknown vertex predictor 4");
  }
}

// An earlier vertex named by its place along the border (version 9): after the starting triangle v0 v1 v2
// the border is its three edges, the gate v0 -> v1 first. Place 3 is the start of the second edge after
// the gate, v2 (the triangle v1 v0 v2); place 5 would be the third, which is the gate itself; place 0
// names the vertex by its number instead. A reader walks at most 1,024 edges.
TEST(CnbDamage, BorderPlacesThatCannotBeRight) {
  const auto error_for = [](std::initializer_list<uint64_t> place) {
    cnb::ByteWriter w = scene_header_and_root();
    traversal_start(w, 3, 2, 0);  // no period, no predictors named
    w.byte_in(4, cnb::gate_symbol_context(0));  // an earlier vertex
    const size_t place_at = w.bytes().size();
    w.varuint_in(*place.begin(), cnb::Field::index, cnb::border_place_context());
    for (auto v = place.begin() + 1; v != place.end(); ++v) w.varuint(*v, cnb::Field::index);
    w.varuint(0, cnb::Field::count);  // children
    return std::pair{place_at, error_of(cnb::pack(w, CnbOptions::Coder::deflate, nullptr))};
  };
  EXPECT_EQ(error_for({3}).second, "(read without error)");
  EXPECT_EQ(error_for({0, 0}).second, "(read without error)");  // by number: the last vertex, v2
  {
    const auto [place_at, error] = error_for({5});
    EXPECT_EQ(error, name + ": decoded byte " + std::to_string(place_at) + ": border place 5 beyond the gate's border");
  }
  {
    const auto [place_at, error] = error_for({2049});
    EXPECT_EQ(error, name + ": decoded byte " + std::to_string(place_at) +
                         ": border place 2049 beyond the 1024 edges a reader walks");
  }
  {  // place 1: v1, the gate's own end, so the triangle v1 v0 v1
    const auto [place_at, error] = error_for({1});
    EXPECT_EQ(error, name + ": decoded byte " + std::to_string(place_at - 1) + ": a triangle with a repeated vertex");
  }
}

// A surface whose weights are factors (mode 3, version 6 on): a version 5 file knew no such mode.
TEST(CnbDamage, WeightFactorsBeforeVersion6) {
  NurbsSurface s;
  s.u_order = s.v_order = 2;
  s.u_count = 3;
  s.v_count = 2;
  s.u_knots = {0, 0, 1, 2, 2};
  s.v_knots = {0, 0, 1, 1};
  s.points = {{0, 0, 0}, {1, 0, 0.5}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0.5}, {2, 1, 0}};
  s.weights = {0.5, 2, 1, 0.125, 0.5, 0.25};
  Scene scene;
  scene.root.shapes.push_back({"", TrimmedSurface{s, {}}, std::nullopt});
  CnbOptions options;
  options.coder = CnbOptions::Coder::deflate;
  CnbWriteReport report;
  const std::string file = write_cnb(scene, options, &report);
  ASSERT_EQ(report.factored_weight_nets, 1);
  EXPECT_EQ(std::get<TrimmedSurface>(read_cnb(file, name).root.shapes[0].geometry).surface.weights, s.weights);
  const std::string error = error_of(with_version(file, 5));
  EXPECT_EQ(error.substr(0, name.size() + 15), name + ": decoded byte ");
  EXPECT_EQ(error.substr(error.size() - 23), ": unknown weight mode 3");
}

// A group with copies (shape kind 7) of one mesh, one triangle, then one copy record: mesh `member`,
// source `source`, turn `turn`, no move. Returns the error and the offsets of the copy's fields.
struct CopyFields {
  std::string file, error;
  size_t kind_at, member_at, source_at, turn_at;
};
CopyFields one_copy_error(uint64_t member, uint64_t source, uint8_t turn) {
  cnb::ByteWriter w = scene_header_and_root();
  w.varuint(1, cnb::Field::count);  // the node's shapes
  const size_t kind_at = w.bytes().size();
  w.byte(7);
  w.varuint(1, cnb::Field::count);  // one mesh: a group for its copies
  w.byte(0);
  w.text("pads");
  one_triangle_traversal(w);
  // (one mesh: no member codes)
  w.varuint(1, cnb::Field::count);  // one run of copies
  CopyFields f;
  f.kind_at = kind_at;
  f.member_at = w.bytes().size();
  w.varuint(member, cnb::Field::index);
  f.source_at = w.bytes().size();
  w.varuint(source, cnb::Field::index);
  f.turn_at = w.bytes().size();
  w.byte(turn);
  w.varuint(0, cnb::Field::count);  // one copy in the run
  for (int k = 0; k < 3; ++k) w.varsint(k == 0 ? 5 : 0, cnb::Field::point);
  w.varuint(0, cnb::Field::count);  // children
  f.file = cnb::pack(w, CnbOptions::Coder::deflate, nullptr);
  f.error = error_of(f.file);
  return f;
}

// Copies naming a mesh beyond the group, a turn beyond the 48, or a piece the mesh does not have.
TEST(CnbDamage, CopiesThatCannotBeRight) {
  {  // well formed: the triangle, and its copy 5 steps along x
    const CopyFields f = one_copy_error(0, 0, 0);
    ASSERT_EQ(f.error, "(read without error)");
    const Scene scene = read_cnb(f.file, name);
    ASSERT_EQ(scene.root.shapes.size(), 1u);
    const auto& mesh = std::get<TriangleMesh>(scene.root.shapes[0].geometry);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    ASSERT_EQ(mesh.positions.size(), 6u);
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(mesh.positions[mesh.triangles[1][k]] - mesh.positions[mesh.triangles[0][k]], Eigen::Vector3d(5, 0, 0));
    // Version 4 knew no shape kind 7.
    EXPECT_EQ(error_of(with_version(f.file, 4)),
              name + ": decoded byte " + std::to_string(f.kind_at) + ": unknown shape kind 7");
  }
  {
    const CopyFields f = one_copy_error(1, 0, 0);
    EXPECT_EQ(f.error, name + ": decoded byte " + std::to_string(f.member_at) + ": a copy in mesh 2 of a group of 1");
  }
  {
    const CopyFields f = one_copy_error(0, 0, 48);
    EXPECT_EQ(f.error, name + ": decoded byte " + std::to_string(f.turn_at) + ": copy turn 48 above 47");
  }
  {
    const CopyFields f = one_copy_error(0, 1, 0);
    EXPECT_EQ(f.error, name + ": decoded byte " + std::to_string(f.source_at) + ": copy source 1 beyond the 1 pieces of mesh 1");
  }
}

}  // namespace
}  // namespace cadnurbs
