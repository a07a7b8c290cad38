#pragma once
// What the curve and surface readers share: refusing class data with a message that names the class,
// validating what they return, reading homogeneous control points, and reading a nested curve object.
#include <string>
#include <utility>
#include <vector>

#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"
#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

// Throws ArchiveError "<file>: chunk 0x... at offset N: <class_name>: <reason>".
[[noreturn]] void refuse(const ArchiveReader& reader, const char* class_name, const std::string& reason);

// Reads the one-byte chunk version a class writes first; refuses a major version other than `major`.
// Returns the minor version.
int expect_major_version(ArchiveReader& reader, const char* class_name, int major);

// An int32 count of `element_size`-byte elements that follow; refused (naming the class and `what`) when
// negative or when the elements would not fit in what is left of the chunk, before anything is allocated.
std::size_t read_count(ArchiveReader& reader, const char* class_name, std::size_t element_size,
                       const std::string& what);

// The dimension field of a curve or surface: refused unless 2 or 3. Returns it.
int expect_dimension(const ArchiveReader& reader, const char* class_name, int dimension);

// A NURBS header's order and control point count (per direction for a surface, `direction` "u" or "v";
// "" for a curve): refused unless order >= 2 and count >= order.
void expect_order_and_count(const ArchiveReader& reader, const char* class_name, const std::string& direction,
                            int order, int count);

// The geometry after core's validate(); a fault is refused as above with validate's reason.
NurbsCurve checked(const ArchiveReader& reader, const char* class_name, NurbsCurve curve);
NurbsSurface checked(const ArchiveReader& reader, const char* class_name, NurbsSurface surface);

// `count` control points of `dimension` (2 or 3) doubles, plus a weight when `rational`, homogeneous as
// openNURBS stores them (w*x, w*y[, w*z], w). Euclidean points are x * (1.0 / w) (openNURBS's GetCV
// arithmetic, see curve_objects.hpp); z = 0 in 2D. Refuses a weight that is not > 0 (also NaN).
void read_control_points(ArchiveReader& reader, const char* class_name, int dimension, bool rational,
                         std::size_t count, std::vector<Eigen::Vector3d>& points, std::vector<double>& weights);

// Reads the nested object (TCODE_OPENNURBS_CLASS chunk) at the reader's offset with read_object and
// returns it if it is a curve; refuses anything else, naming `what` ("segment 2") and the class read.
// Refuses to open one when kMaxOpenChunks chunks are open already: a polycurve of polycurves recurses once
// per level, and a file of nothing but nested headers would otherwise nest deep enough to overflow the
// stack (a real file nests a few levels: table, record, object, Brep, its curves).
inline constexpr int kMaxOpenChunks = 64;
NurbsCurve nested_curve(ArchiveReader& reader, const char* class_name, const std::string& what);

// openNURBS's ON_Interval (two doubles), refused unless t0 < t1; `what` names it ("domain").
std::pair<double, double> read_increasing_interval(ArchiveReader& reader, const char* class_name,
                                                   const std::string& what);

// An int32 knot count and the knots of a NURBS of `order` with `count` control points (`direction` as for
// expect_order_and_count), refused unless there are exactly order + count - 2. Returned as the full
// vector (see with_end_knots).
std::vector<double> read_knots(ArchiveReader& reader, const char* class_name, const std::string& direction,
                               int order, int count);

// openNURBS keeps order + count - 2 knots (no end knots); core keeps the full vector: the first and the
// last stored knot once more. `stored` must not be empty.
std::vector<double> with_end_knots(const std::vector<double>& stored);

}  // namespace cadnurbs::rhino
