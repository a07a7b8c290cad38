#pragma once
// Colours in a .cnb payload (docs/cnb.md, "Colours"). Every colour is kept to within 1/131070 per
// component. From format version 4 a colour is one of the last 16 met in the file (coded by its place),
// or a whole number of 255ths or of thousandths per component (the colours of CAD files are mostly one of
// these: KiCad writes 0.824 and 210/255 as float32), or else three multiples of 1/65535 as before version 4.
#include <cstdint>
#include <vector>

#include "core/scene.hpp"
#include "formats/cnb/cnb_stream.hpp"

namespace cadnurbs::cnb {

constexpr size_t colour_cache_size = 16;

// The colours met so far in a file, most recent first; writer and reader update it in the same order.
struct ColourCache {
  std::vector<Colour> recent;
};

void write_colour(ByteWriter& out, const Colour& colour, ColourCache& cache);
// `version`: the file's format version (before 4: three multiples of 1/65535, no cache). Refuses
// (PayloadError) a component above 1 and a place beyond the colours met.
Colour read_colour(ByteReader& in, ColourCache& cache, uint8_t version);

}  // namespace cadnurbs::cnb
