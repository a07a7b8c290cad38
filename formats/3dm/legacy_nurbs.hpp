#pragma once
// The NURBS records of Rhino 1's legacy geometry (version 1 files) as core curves and surfaces. Layouts
// from openNURBS's ReadV1_TCODE_LEGACY_SPLSTUFF / SRFSTUFF / CRVSTUFF (opennurbs_archive.cpp): fields
// are packed with no chunk version, counts are one- and two-byte integers.
//
// Every "stuff" record sits in a wrapper chunk of its kind (TCODE_LEGACY_SPL holds TCODE_LEGACY_SPLSTUFF,
// ...); the wrapper may hold other chunks first (attributes), which openNURBS steps over, and ends in the
// 16-bit CRC V1 legacy chunks carry (2 bytes; not checked here: end_chunk steps over it).
//
// Each function refuses what openNURBS refuses, plus what core's validate() refuses, with ArchiveError
// "<file>: chunk 0x... at offset N: <record>: <reason>" naming the innermost open chunk.
#include <cstdint>

#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"
#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

// Steps over chunks until one of typecode `stuff` and opens it (close it with end_chunk). Refuses
// ("no <name> chunk in ...") when the enclosing chunk ends first.
void open_legacy_chunk(ArchiveReader& reader, std::uint32_t stuff, const char* name);

// TCODE_LEGACY_SPLSTUFF: dimension, rational flag, order (1 byte each), control point count (uint16),
// closed and form bytes, bounding box, a clamped-ends flag when order > 2 (bit 0: the first order - 1
// knots are equal and stored once, bit 1: the last), the knots (order + count - 2, ends as the flag
// says), the control points, Euclidean with the weight after them when rational. A line (order 2, two
// points) stored with decreasing knots has them negated, as openNURBS does. Refuses dimension other
// than 2 or 3, order < 2, fewer points than the order.
NurbsCurve read_legacy_spline(ArchiveReader& reader);

// TCODE_LEGACY_CRVSTUFF: dimension, closed flag, segment count (int16, >= 1), bounding box, then one
// TCODE_LEGACY_SPL chunk per segment. One segment is returned as it is; more are joined (join_segments of
// curve_objects.hpp) over the polycurve's parameters: the first segment's domain, each next one appended
// with its own length of domain. Refuses a chunk other than TCODE_LEGACY_SPL in the segment list, and
// segments that cannot be joined ("joining the segments: <reason>").
NurbsCurve read_legacy_curve(ArchiveReader& reader);

// TCODE_LEGACY_SRFSTUFF: dimension, form, u and v degree, u and v span counts (uint16; count = order - 1 +
// spans), u and v rational flags (0 no, 1 Euclidean, 2 homogeneous; the v flag overrides when set),
// closed and singular bytes per direction, bounding box, u knots, v knots, then the points with the v
// index running fastest (transposed into core's u-fastest order). Euclidean rational points are kept as
// they are; homogeneous ones become x * (1 / w) (curve_objects.hpp's convention).
NurbsSurface read_legacy_surface(ArchiveReader& reader);

}  // namespace cadnurbs::rhino
