// The pieces of a site (`batch --site`, issue 40): a part's picture against the view's closed form (a cube
// inside the circle its bounding sphere fills, covering the share of it its projection covers), PNG bytes
// read back by libpng, base64 both ways, URL paths, and a part's page with and without its picture.
#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <set>

#include "formats/png/indexed_png.hpp"
#include "formats/web_text/base64.hpp"
#include "formats/web_text/markup_text.hpp"
#include "web/page/site_page.hpp"
#include "web/thumbnail/part_thumbnail.hpp"

namespace cadnurbs {
namespace {

// A unit cube centred on the origin, one face colour, its 12 triangles with outward normals.
SceneArrays unit_cube(float red, float green, float blue) {
  SceneArrays cube;
  for (int corner = 0; corner < 8; ++corner)
    for (int axis = 0; axis < 3; ++axis) cube.positions.push_back((corner >> axis & 1) ? 0.5 : -0.5);
  cube.normals.assign(cube.positions.size(), 0.0f);
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) cube.indices.insert(cube.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  cube.face_first_triangle = {0, 12};
  cube.face_colours = {red, green, blue};
  return cube;
}

TEST(PartThumbnail, ACubeFillsItsShareOfTheCircleItsBoundingSphereMakesInShadesOfItsColour) {
  const int width = 160, height = 120;
  const IndexedImage image = part_thumbnail(unit_cube(1, 0, 0), width, height);
  ASSERT_EQ(image.pixels.size(), size_t(width * height));
  // The fitted view puts the bounding sphere (radius sqrt(3)/2) just inside the vertical field of view: it
  // is seen as the circle of radius height/2 about the centre.
  long drawn = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (image.pixels[y * width + x] == 0) continue;
      ++drawn;
      EXPECT_LE(std::hypot(x + 0.5 - width / 2.0, y + 0.5 - height / 2.0), height / 2.0 + 1) << x << "," << y;
    }
  // Seen along d = (1, -1.4, 0.9), a unit cube covers |dx| + |dy| + |dz| over |d| = 1.695 (orthographic);
  // the sphere's disc pi 3/4 = 2.356: 0.72 of it, within perspective's few per cent.
  const double circle = M_PI * (height / 2.0) * (height / 2.0);
  EXPECT_GT(drawn / circle, 0.66);
  EXPECT_LT(drawn / circle, 0.78);
  // White, then shades of red: three faces seen, each lit alike all over.
  ASSERT_GE(image.palette.size(), 6u);
  EXPECT_EQ(std::vector<uint8_t>(image.palette.begin(), image.palette.begin() + 3), (std::vector<uint8_t>{255, 255, 255}));
  EXPECT_LE(image.palette.size() / 3, 4u);
  for (size_t c = 1; c < image.palette.size() / 3; ++c) {
    EXPECT_GT(image.palette[3 * c], 0);
    EXPECT_EQ(image.palette[3 * c + 1], 0);
    EXPECT_EQ(image.palette[3 * c + 2], 0);
  }
}

TEST(PartThumbnail, NoTrianglesIsAWhitePictureAndNoPixelsIsRefused) {
  const IndexedImage image = part_thumbnail(SceneArrays{}, 4, 3);
  EXPECT_EQ(image.pixels, std::vector<uint8_t>(12, 0));
  EXPECT_EQ(image.palette, (std::vector<uint8_t>{255, 255, 255}));
  EXPECT_THROW(part_thumbnail(SceneArrays{}, 0, 3), std::invalid_argument);
}

// The PNG read back by libpng as RGB.
std::vector<uint8_t> decoded_rgb(const std::string& png, int& width, int& height) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, png.data(), png.size())) return {};
  image.format = PNG_FORMAT_RGB;
  std::vector<uint8_t> rgb(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr)) return {};
  width = static_cast<int>(image.width);
  height = static_cast<int>(image.height);
  return rgb;
}

TEST(IndexedPng, EveryPaletteSizeReadsBackPixelForPixel) {
  for (const int colours : {1, 2, 3, 5, 17, 256}) {
    IndexedImage image;
    image.width = 13;  // rows that end inside a byte at 1, 2 and 4 bits per pixel
    image.height = 7;
    for (int c = 0; c < colours; ++c) image.palette.insert(image.palette.end(), {uint8_t(c), uint8_t(255 - c), uint8_t(c * 7)});
    for (int p = 0; p < image.width * image.height; ++p) image.pixels.push_back(uint8_t((p * 31 + p / 5) % colours));
    const std::string png = indexed_png(image);
    int width = 0, height = 0;
    const std::vector<uint8_t> rgb = decoded_rgb(png, width, height);
    ASSERT_EQ(width, 13) << colours;
    ASSERT_EQ(height, 7);
    for (int p = 0; p < width * height; ++p)
      for (int k = 0; k < 3; ++k) ASSERT_EQ(rgb[3 * p + k], image.palette[3 * image.pixels[p] + k]) << colours << " " << p;
  }
}

TEST(IndexedPng, RefusesWhatItCannotWrite) {
  IndexedImage image;
  image.width = 2;
  image.height = 1;
  image.palette = {0, 0, 0};
  image.pixels = {0, 1};
  EXPECT_THROW(indexed_png(image), std::invalid_argument);  // an index past the palette
  image.pixels = {0};
  EXPECT_THROW(indexed_png(image), std::invalid_argument);  // pixels not width x height
  image.pixels = {0, 0};
  image.palette.assign(3 * 257, 0);
  EXPECT_THROW(indexed_png(image), std::invalid_argument);  // 257 colours
}

TEST(Base64, BytesOfBase64UndoesBase64AndRefusesWhatIsNotBase64) {
  std::string all;
  for (int b = 0; b < 256; ++b) all += static_cast<char>(b);
  for (size_t n = 0; n <= 6; ++n) EXPECT_EQ(bytes_of_base64(base64(all.substr(0, n))), all.substr(0, n)) << n;
  EXPECT_EQ(bytes_of_base64(base64(all)), all);
  EXPECT_EQ(bytes_of_base64("TWFu\nTWE=\n"), "ManMa");
  EXPECT_THROW(bytes_of_base64("TWF"), std::invalid_argument);
  EXPECT_THROW(bytes_of_base64("TW*u"), std::invalid_argument);
  EXPECT_THROW(bytes_of_base64("TW=u"), std::invalid_argument);
}

TEST(UrlPath, KeepsFoldersAndEncodesWhatAUrlReadsOtherwise) {
  EXPECT_EQ(url_path("Package_QFP.3dshapes/LQFP-48_7x7mm.step.html"), "Package_QFP.3dshapes/LQFP-48_7x7mm.step.html");
  EXPECT_EQ(url_path("a b/c#1?.step,x"), "a%20b/c%231%3F.step%2Cx");
  EXPECT_EQ(url_path("\xc3\xa9"), "%C3%A9");
}

TEST(SitePartPage, ShowsThePictureWhenThereIsOneAndNamesTheSharedFiles) {
  SitePartPage page;
  page.name = "a b.step";
  page.family = "f";
  page.library = "L";
  page.cnb_file = "a b.step.cnb";
  page.cnb_bytes = 1234;
  page.root = "../";
  std::string without;
  try {
    without = site_part_page(page);
  } catch (const std::runtime_error&) {
    GTEST_SKIP() << "built without the browser module";
  }
  EXPECT_EQ(without.find("<img"), std::string::npos);
  EXPECT_NE(without.find("<script src=\"../cadnurbs-assets/site_start.js\" data-name=\"a b.step\" data-part=\"a%20b.step.cnb\"></script>"),
            std::string::npos);
  page.picture_file = "a b.step.png";
  const std::string with = site_part_page(page);
  EXPECT_NE(with.find("<div id=\"cadnurbs-view\"><img id=\"cadnurbs-picture\" elementtiming=\"picture\" src=\"a%20b.step.png\" alt=\"\"></div>"),
            std::string::npos);
}

}  // namespace
}  // namespace cadnurbs
