#include "formats/png/indexed_png.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <stdexcept>

namespace cadnurbs {

namespace {

// What libpng's callbacks reach: the bytes written so far and the first error's text.
struct PngSink {
  std::string bytes;
  char error[200] = "";
};

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  static_cast<PngSink*>(png_get_io_ptr(png))->bytes.append(reinterpret_cast<const char*>(data), length);
}

void flush_nothing(png_structp) {}

// libpng's errors return by longjmp to write_png's setjmp (no C++ exception crosses libpng's C frames).
void libpng_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
  std::snprintf(sink->error, sizeof sink->error, "%s", message);
  png_longjmp(png, 1);
}

void libpng_warning(png_structp, png_const_charp) {}

// Packs one row of indices at `bits` per pixel, the first pixel in the high bits (PNG's order).
std::vector<png_byte> packed_row(const uint8_t* row, int width, int bits) {
  std::vector<png_byte> packed((static_cast<size_t>(width) * bits + 7) / 8, 0);
  for (int x = 0; x < width; ++x) {
    const size_t bit = static_cast<size_t>(x) * bits;
    packed[bit / 8] |= static_cast<png_byte>(row[x] << (8 - bits - bit % 8));
  }
  return packed;
}

// The libpng calls, with nothing to destroy on their frame, since an error leaves it by longjmp. False
// with sink->error set when libpng failed.
bool write_png(PngSink* sink, int width, int height, int bits, const png_color* palette, int colours, png_bytepp rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, sink, libpng_error, libpng_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, sink, append_bytes, flush_nothing);
  png_set_compression_level(png, 9);
  png_set_IHDR(png, info, width, height, bits, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_PLTE(png, info, palette, colours);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::string indexed_png(const IndexedImage& image) {
  if (image.width <= 0 || image.height <= 0) throw std::invalid_argument("png: the image is empty");
  if (image.pixels.size() != static_cast<size_t>(image.width) * image.height)
    throw std::invalid_argument("png: the pixels are not width x height");
  const size_t colours = image.palette.size() / 3;
  if (colours == 0 || colours > 256 || image.palette.size() % 3 != 0)
    throw std::invalid_argument("png: the palette needs 1 to 256 colours of 3 bytes");
  for (const uint8_t index : image.pixels)
    if (index >= colours) throw std::invalid_argument("png: a pixel's index is past the palette");
  const int bits = colours <= 2 ? 1 : colours <= 4 ? 2 : colours <= 16 ? 4 : 8;
  std::vector<png_color> palette(colours);
  for (size_t c = 0; c < colours; ++c) palette[c] = {image.palette[3 * c], image.palette[3 * c + 1], image.palette[3 * c + 2]};
  std::vector<std::vector<png_byte>> rows;
  std::vector<png_bytep> row_pointers;
  for (int y = 0; y < image.height; ++y)
    rows.push_back(packed_row(image.pixels.data() + static_cast<size_t>(y) * image.width, image.width, bits));
  for (auto& row : rows) row_pointers.push_back(row.data());
  PngSink sink;
  if (!write_png(&sink, image.width, image.height, bits, palette.data(), static_cast<int>(colours), row_pointers.data()))
    throw std::runtime_error(std::string("png: ") + (sink.error[0] ? sink.error : "libpng could not start"));
  return std::move(sink.bytes);
}

}  // namespace cadnurbs
