// Colours (formats/cnb/cnb_colours.hpp): every colour decodes within half of 1/65535 per component, the
// whole numbers of thousandths and of 255ths that CAD files write (as float32) decode to those numbers,
// and a colour met before costs a byte.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"

namespace cadnurbs {
namespace {

// A scene of one node per colour, each holding one triangle.
Scene scene_of(const std::vector<Colour>& colours) {
  Scene scene;
  for (size_t i = 0; i < colours.size(); ++i) {
    SceneNode node;
    node.name = "n" + std::to_string(i);
    node.colour = colours[i];
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    node.shapes.push_back({"", mesh, std::nullopt});
    scene.root.children.push_back(node);
  }
  return scene;
}

size_t payload_bytes(const Scene& scene) {
  CnbOptions options;
  options.max_deviation = 0.01;
  CnbWriteReport report;
  write_cnb(scene, options, &report);
  return report.payload_bytes;
}

TEST(CnbColours, EachColourWithinHalfASixteenBitStep) {
  const std::vector<Colour> colours = {
      {static_cast<float>(0.824), static_cast<float>(0.820), static_cast<float>(0.781)},  // KiCad's, as float32
      {static_cast<float>(210 / 255.0), static_cast<float>(209 / 255.0), static_cast<float>(199 / 255.0)},
      {0.123456, 0.5, 0.999999},
      {0, 1, 0.2}};
  CnbOptions options;
  options.max_deviation = 0.01;
  const Scene decoded = read_cnb(write_cnb(scene_of(colours), options), "colours.cnb");
  ASSERT_EQ(decoded.root.children.size(), colours.size());
  for (size_t i = 0; i < colours.size(); ++i) {
    const Colour c = decoded.root.children[i].colour.value();
    EXPECT_LE(std::abs(c.r - colours[i].r), 0.5 / 65535) << i;
    EXPECT_LE(std::abs(c.g - colours[i].g), 0.5 / 65535) << i;
    EXPECT_LE(std::abs(c.b - colours[i].b), 0.5 / 65535) << i;
  }
  EXPECT_EQ(decoded.root.children[0].colour->r, 0.824);  // the thousandths the file meant
  EXPECT_EQ(decoded.root.children[1].colour->r, 210 / 255.0);
}

// Ten nodes of one colour: the first costs a tag and three thousandths (at most 7 bytes), each repeat
// one byte; as three multiples of 1/65535 every time they took 90.
TEST(CnbColours, AColourMetBeforeCostsAByte) {
  const Colour kicad_grey{static_cast<float>(0.824), static_cast<float>(0.820), static_cast<float>(0.781)};
  Scene coloured = scene_of(std::vector<Colour>(10, kicad_grey));
  Scene plain = coloured;
  for (auto& node : plain.root.children) node.colour.reset();
  EXPECT_LE(payload_bytes(coloured) - payload_bytes(plain), 7u + 9u);
}

}  // namespace
}  // namespace cadnurbs
