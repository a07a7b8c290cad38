#pragma once
// An image of at most 256 colours as a PNG file's bytes (libpng): palette colour type, at the fewest bits
// per pixel that index the palette (1, 2, 4 or 8), deflated at zlib's level 9. Thumbnails of parts have a
// few shades of a few colours, where a palette costs a third of RGB's bytes before deflate.
#include <cstdint>
#include <string>
#include <vector>

namespace cadnurbs {

struct IndexedImage {
  int width = 0, height = 0;
  std::vector<uint8_t> palette;  // 3 per colour (red, green, blue), at most 256 colours
  std::vector<uint8_t> pixels;   // width * height palette indices, row by row from the top
};

// Throws std::invalid_argument for an empty image, pixels of another count, a palette of no colour or
// more than 256, or an index past the palette; std::runtime_error when libpng fails.
std::string indexed_png(const IndexedImage& image);

}  // namespace cadnurbs
