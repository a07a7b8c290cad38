// Our own STEP reader against OpenCASCADE's, side by side in one run (issue 37's speed check): each file
// read natively (parse + build + trimming curves, into the Scene) and through OCCT (read_step: parse,
// transfer, and the faces converted to the same Scene), alternately, the better of `rounds` runs of each.
// Files the native reader hands to OCCT are listed with the entity and reason, counted by reason.
// Usage: step_read_speed [--rounds N] [--native-only] FILE_OR_DIR...   (directories: every .step/.stp below them)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "formats/step/native/read_step_native.hpp"
#include "formats/step/step_reader.hpp"

namespace {

double seconds(const std::chrono::steady_clock::time_point& start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The reason without its entity number, for counting ("#12 TRIMMED_CURVE: ..." -> "TRIMMED_CURVE: ...").
std::string reason_kind(const std::string& what) {
  if (what.rfind('#', 0) == 0) {
    const auto space = what.find(' ');
    if (space != std::string::npos) return what.substr(space + 1);
  }
  return what;
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 1;
  bool occt = true;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--rounds" && i + 1 < argc) {
      rounds = std::max(1, std::atoi(argv[++i]));
      continue;
    }
    if (a == "--native-only") {
      occt = false;
      continue;
    }
    if (std::filesystem::is_directory(a)) {
      for (const auto& entry : std::filesystem::recursive_directory_iterator(a)) {
        const std::string ext = lower(entry.path().extension().string());
        if (entry.is_regular_file() && (ext == ".step" || ext == ".stp")) files.push_back(entry.path().string());
      }
    } else {
      files.push_back(a);
    }
  }
  std::sort(files.begin(), files.end());
  double native_total = 0, occt_total = 0, native_read_total = 0;
  int read = 0, refused = 0, failed = 0;
  std::map<std::string, int> reasons;
  for (const auto& file : files) {
    double native_best = 1e300, occt_best = 1e300;
    std::string refusal;
    for (int r = 0; r < rounds; ++r) {
      auto start = std::chrono::steady_clock::now();
      try {
        const auto translation = cadnurbs::read_step_native(file);
        native_best = std::min(native_best, seconds(start));
      } catch (const std::exception& e) {
        refusal = e.what();
        native_best = std::min(native_best, seconds(start));
      }
      if (!occt) continue;
      start = std::chrono::steady_clock::now();
      try {
        const auto translation = cadnurbs::read_step(file);
      } catch (const std::exception& e) {
        std::printf("OCCT failed: %s: %s\n", file.c_str(), e.what());
        ++failed;
      }
      occt_best = std::min(occt_best, seconds(start));
    }
    if (refusal.empty()) {
      ++read;
      native_read_total += native_best;
    } else {
      ++refused;
      ++reasons[reason_kind(refusal)];
      std::printf("to OCCT: %s: %s\n", file.c_str(), refusal.c_str());
    }
    native_total += native_best;
    occt_total += occt_best;
    if (occt)
      std::printf("%-70s native %8.4f s  OCCT %8.4f s  %6.1fx%s\n", file.c_str(), native_best, occt_best,
                  occt_best / native_best, refusal.empty() ? "" : "  (refused)");
    else
      std::printf("%-70s native %8.4f s%s\n", file.c_str(), native_best, refusal.empty() ? "" : "  (refused)");
  }
  std::printf("\n%zu files: %d read natively, %d handed to OCCT (%.1f %%), %d OCCT failures\n", files.size(), read,
              refused, 100.0 * refused / std::max<std::size_t>(1, files.size()), failed);
  if (occt)
    std::printf("native total %.2f s (of which read natively %.2f s), OCCT total %.2f s: OCCT / native %.1fx\n",
                native_total, native_read_total, occt_total, occt_total / native_total);
  else
    std::printf("native total %.2f s (of which read natively %.2f s)\n", native_total, native_read_total);
  for (const auto& [reason, count] : reasons) std::printf("%5d  %s\n", count, reason.c_str());
  return 0;
}
