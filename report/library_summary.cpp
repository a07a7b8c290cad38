#include "report/library_summary.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <regex>

namespace cadnurbs {

namespace {

constexpr int kLowestPower = -8;  // bins of powers of 2: [0, 1/256), [1/256, 1/128), ..., [4, inf)
constexpr int kHighestPower = 2;

std::vector<RatioBin> empty_bins() {
  std::vector<RatioBin> bins;
  bins.push_back({0, std::ldexp(1.0, kLowestPower), 0});
  for (int p = kLowestPower; p < kHighestPower; ++p) bins.push_back({std::ldexp(1.0, p), std::ldexp(1.0, p + 1), 0});
  bins.push_back({std::ldexp(1.0, kHighestPower), std::numeric_limits<double>::infinity(), 0});
  return bins;
}

}  // namespace

const RepresentationFigures* smallest_smooth_representation(const PartRecord& record) {
  const RepresentationFigures* nurbs = smallest_representation(record, RepresentationKind::nurbs);
  return nurbs ? nurbs : smallest_representation(record, RepresentationKind::loop);
}

double compression_ratio(const PartRecord& record) {
  const RepresentationFigures* mesh = smallest_representation(record, RepresentationKind::mesh);
  const RepresentationFigures* smooth = smallest_smooth_representation(record);
  if (!mesh || !smooth || delivered_bytes(*mesh) <= 0) return std::numeric_limits<double>::quiet_NaN();
  return double(delivered_bytes(*smooth)) / double(delivered_bytes(*mesh));
}

std::string failure_reason(const std::string& error) {
  // A place in the file, or a path (a file written on the way, a node path such as scene/node 0/shape 1).
  static const std::regex location(
      R"(^((line \d+|entity #\d+|object \d+( \([^)]*\))?|face \d+)(, [^:]*)?|[^:]*/[^:]*|[^\s:]+\.[A-Za-z0-9]+): )");
  static const std::regex digits(R"(\d+)");
  static const std::regex aside(R"(\s*\([^()]*\)\s*$)");
  std::string reason = std::regex_replace(error, location, "", std::regex_constants::format_first_only);
  reason = std::regex_replace(reason, aside, "");
  reason = std::regex_replace(reason, digits, "N");
  return reason.empty() ? error : reason;
}

LibrarySummary summarise_library(const std::vector<PartRecord>& records) {
  LibrarySummary summary;
  summary.ratio_bins = empty_bins();
  std::map<std::string, std::size_t> total_of;  // key -> index in summary.totals
  std::map<std::string, std::size_t> reason_of;
  for (const PartRecord& record : records) {
    ++summary.parts;
    if (record.failed) {
      ++summary.failed;
      const std::string reason = failure_reason(record.error);
      const auto [at, added] = reason_of.emplace(reason, summary.failures.size());
      if (added) summary.failures.push_back({reason, {}});
      summary.failures[at->second].parts.push_back(record.input);
      continue;
    }
    ++summary.measured;
    for (const RepresentationFigures& r : record.representations) {
      const auto [at, added] = total_of.emplace(r.key, summary.totals.size());
      if (added) summary.totals.push_back({r.key, r.label, r.kind, 0, 0, 0});
      RepresentationTotal& total = summary.totals[at->second];
      ++total.parts;
      total.bytes += r.bytes;
      total.gzip_bytes += r.gzip_bytes;
    }
    const double ratio = compression_ratio(record);
    if (std::isnan(ratio)) continue;
    ++summary.ratio_parts;
    if (ratio < 1) ++summary.smaller_than_mesh;
    for (RatioBin& bin : summary.ratio_bins)
      if (ratio >= bin.low && ratio < bin.high) {
        ++bin.parts;
        break;
      }
  }
  std::stable_sort(summary.failures.begin(), summary.failures.end(), [](const FailureReason& a, const FailureReason& b) {
    return a.parts.size() != b.parts.size() ? a.parts.size() > b.parts.size() : a.reason < b.reason;
  });
  return summary;
}

}  // namespace cadnurbs
