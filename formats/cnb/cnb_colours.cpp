#include "formats/cnb/cnb_colours.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace cadnurbs::cnb {

namespace {

// The tag before a version 4 colour; a tag of cached_colour + i names the colour i + 1 places back.
enum ColourTag : uint8_t { sixteen_bits = 0, thousandths = 1, two_hundred_fifty_fifths = 2, cached_colour = 3 };
// The whole steps per unit each value tag counts in.
constexpr uint64_t steps_of[cached_colour] = {65535, 1000, 255};

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

// The colour as the reader will decode it from `counts` whole steps of the tag (so that the cache holds the
// same values on both sides).
Colour decoded(const std::array<uint64_t, 3>& counts, uint8_t tag) {
  const double steps = static_cast<double>(steps_of[tag]);
  return {static_cast<double>(counts[0]) / steps, static_cast<double>(counts[1]) / steps,
          static_cast<double>(counts[2]) / steps};
}

void remember(ColourCache& cache, const Colour& c, size_t place) {
  if (place < cache.recent.size()) cache.recent.erase(cache.recent.begin() + static_cast<long>(place));
  cache.recent.insert(cache.recent.begin(), c);
  if (cache.recent.size() > colour_cache_size) cache.recent.pop_back();
}

}  // namespace

void write_colour(ByteWriter& out, const Colour& colour, ColourCache& cache) {
  const auto c = components(colour);
  uint8_t tag = sixteen_bits;  // the coarsest steps the colour is whole in: 255ths, then thousandths
  for (uint8_t t : {two_hundred_fifty_fifths, thousandths})
    if (tag == sixteen_bits && whole_steps(c, static_cast<double>(steps_of[t]))) tag = t;
  std::array<uint64_t, 3> counts;
  for (int k = 0; k < 3; ++k) counts[k] = static_cast<uint64_t>(std::lround(c[k] * static_cast<double>(steps_of[tag])));
  const Colour value = decoded(counts, tag);
  const auto met = std::find(cache.recent.begin(), cache.recent.end(), value);
  const size_t place = static_cast<size_t>(met - cache.recent.begin());
  if (met != cache.recent.end()) {
    out.varuint(cached_colour + place, Field::raw);
  } else {
    out.varuint(tag, Field::raw);
    for (uint64_t n : counts) out.varuint(n, Field::raw);
  }
  remember(cache, value, place);
}

Colour read_colour(ByteReader& in, ColourCache& cache, uint8_t version) {
  const size_t tag_at = in.offset();
  const uint64_t tag = version >= 4 ? in.varuint(Field::raw) : uint64_t{sixteen_bits};
  if (tag >= cached_colour) {
    const uint64_t place = tag - cached_colour;
    if (place >= cache.recent.size())
      in.fail("colour " + std::to_string(place + 1) + " back, with " + std::to_string(cache.recent.size()) + " met",
              tag_at);
    const Colour c = cache.recent[place];
    remember(cache, c, place);
    return c;
  }
  std::array<uint64_t, 3> counts;
  for (uint64_t& n : counts) {
    const size_t at = in.offset();
    n = in.varuint(Field::raw);
    if (n > steps_of[tag]) in.fail("colour component " + std::to_string(n) + " above " + std::to_string(steps_of[tag]), at);
  }
  const Colour colour = decoded(counts, static_cast<uint8_t>(tag));
  if (version >= 4) remember(cache, colour, cache.recent.size());
  return colour;
}

}  // namespace cadnurbs::cnb
