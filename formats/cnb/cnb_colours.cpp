#include "formats/cnb/cnb_colours.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace cadnurbs::cnb {

namespace {

// The tag before a version 4 colour; a tag of cached_colour + i names the colour i + 1 places back.
enum ColourTag : uint8_t { sixteen_bits = 0, thousandths = 1, two_hundred_fifty_fifths = 2, cached_colour = 3 };

constexpr double half_step = 0.5 / 65535.0;  // the precision every colour is kept to

std::array<double, 3> components(const Colour& c) {
  return {std::clamp(c.r, 0.0, 1.0), std::clamp(c.g, 0.0, 1.0), std::clamp(c.b, 0.0, 1.0)};
}

// Whether every component is within half_step of a whole number of 1/`steps`.
bool whole_steps(const std::array<double, 3>& c, double steps) {
  for (double v : c)
    if (std::abs(v - std::round(v * steps) / steps) > half_step) return false;
  return true;
}

// The colour as the reader will decode it (so that the cache holds the same values on both sides).
Colour decoded(const std::array<double, 3>& c, uint8_t tag) {
  const double steps = tag == thousandths ? 1000.0 : tag == two_hundred_fifty_fifths ? 255.0 : 65535.0;
  return {std::round(c[0] * steps) / steps, std::round(c[1] * steps) / steps, std::round(c[2] * steps) / steps};
}

void remember(ColourCache& cache, const Colour& c, size_t place) {
  if (place < cache.recent.size()) cache.recent.erase(cache.recent.begin() + static_cast<long>(place));
  cache.recent.insert(cache.recent.begin(), c);
  if (cache.recent.size() > colour_cache_size) cache.recent.pop_back();
}

}  // namespace

void write_colour(ByteWriter& out, const Colour& colour, ColourCache& cache) {
  const auto c = components(colour);
  const uint8_t tag = whole_steps(c, 255.0) ? two_hundred_fifty_fifths : whole_steps(c, 1000.0) ? thousandths : sixteen_bits;
  const Colour value = decoded(c, tag);
  const auto met = std::find(cache.recent.begin(), cache.recent.end(), value);
  const size_t place = static_cast<size_t>(met - cache.recent.begin());
  if (met != cache.recent.end()) {
    out.varuint(cached_colour + place, Field::raw);
  } else {
    out.varuint(tag, Field::raw);
    const double steps = tag == thousandths ? 1000.0 : tag == two_hundred_fifty_fifths ? 255.0 : 65535.0;
    for (double v : c) out.varuint(static_cast<uint64_t>(std::lround(v * steps)), Field::raw);
  }
  remember(cache, value, place);
}

Colour read_colour(ByteReader& in, ColourCache& cache, uint8_t version) {
  const size_t tag_at = in.offset();
  const uint64_t tag = version >= 4 ? in.varuint(Field::raw) : sixteen_bits;
  if (tag >= cached_colour) {
    const uint64_t place = tag - cached_colour;
    if (place >= cache.recent.size())
      in.fail("colour " + std::to_string(place + 1) + " back, with " + std::to_string(cache.recent.size()) + " met",
              tag_at);
    const Colour c = cache.recent[place];
    remember(cache, c, place);
    return c;
  }
  const uint64_t steps = tag == thousandths ? 1000 : tag == two_hundred_fifty_fifths ? 255 : 65535;
  double c[3];
  for (double& v : c) {
    const size_t at = in.offset();
    const uint64_t n = in.varuint(Field::raw);
    if (n > steps)
      in.fail("colour component " + std::to_string(n) + " above " + std::to_string(steps), at);
    v = static_cast<double>(n) / static_cast<double>(steps);
  }
  const Colour colour{c[0], c[1], c[2]};
  if (version >= 4) remember(cache, colour, cache.recent.size());
  return colour;
}

}  // namespace cadnurbs::cnb
