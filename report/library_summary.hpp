#pragma once
// What a whole library's records come to (cadnurbs batch's combined report): counts, bytes per
// representation summed over the parts, the distribution of per-part compression ratios, and the
// failures grouped by reason.
#include <string>
#include <vector>

#include "report/storage_record.hpp"

namespace cadnurbs {

struct RepresentationTotal {
  std::string key, label;  // as in the records (storage_record.hpp)
  RepresentationKind kind = RepresentationKind::nurbs;
  int parts = 0;           // measured parts that have it
  long bytes = 0;          // summed over those parts: files as written
  long gzip_bytes = 0;     // and gzip'd at level 9
};

// Parts whose ratio r lies in [low, high). The first bin has low = 0 and the last high = infinity.
struct RatioBin {
  double low = 0, high = 0;
  int parts = 0;
};

struct FailureReason {
  std::string reason;              // the errors' common form (failure_reason)
  std::vector<std::string> parts;  // inputs that failed so, in record order
};

struct LibrarySummary {
  int parts = 0, measured = 0, failed = 0;
  std::vector<RepresentationTotal> totals;  // in the order keys first appear in the records
  // Per measured part, the compression ratio: the smallest NURBS file (delivered bytes: the smaller of
  // file and gzip'd file) over the smallest mesh file at D; for a part given as a mesh, its fitted Loop
  // control mesh over the smallest mesh file. Bins of powers of 2 from 1/256 to 4; parts with neither
  // a smaller-kind file nor a mesh file are not binned.
  std::vector<RatioBin> ratio_bins;
  int ratio_parts = 0;                   // parts binned
  int smaller_than_mesh = 0;             // of those, the ones whose ratio is below 1
  std::vector<FailureReason> failures;   // most parts first, then by reason
};

// The part's smallest NURBS file, or for a part given as a mesh its Loop control mesh; null when it has
// neither.
const RepresentationFigures* smallest_smooth_representation(const PartRecord& record);

// smallest_smooth_representation's delivered bytes over the smallest mesh file's; NaN when either is
// missing or the mesh file is empty.
double compression_ratio(const PartRecord& record);

// The summary of `records` (any order; a failed record counts in `failed` and its reason only).
LibrarySummary summarise_library(const std::vector<PartRecord>& records);

// A failed record's error in the form its kind shares with others: a leading location ("line 278: ",
// "entity #12: ", "object 3 (ON_Brep): ", a path with a slash, a file name) dropped, each run of digits
// written as N, and a closing parenthesised aside dropped. "line 278: unsupported node
// CoordinateInterpolator (outside the VRML97 subset)" -> "unsupported node CoordinateInterpolator";
// "exceeded 300 s" -> "exceeded N s".
std::string failure_reason(const std::string& error);

}  // namespace cadnurbs
