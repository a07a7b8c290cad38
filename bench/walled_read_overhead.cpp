// What the STEP/IGES wall (converters/walled_read) costs: every corpus STEP and IGES file converted to
// .x3dv by `convert`'s pipeline in a fresh process, once reading in-process and once through the wall,
// alternately, side by side in one run; prints each file's fastest times and the ratio of the totals.
// `walled_read_overhead [ROUNDS [FILE...]]`: 3 rounds and every corpus file by default.
// This executable is its own child: `walled_read_overhead in-process|walled IN OUT` converts one file,
// and it serves `__read-brep` for the wall.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

#include "converters/commands.hpp"
#include "converters/command_line.hpp"
#include "converters/walled_read.hpp"

using namespace cadnurbs;

namespace {

double seconds_of(const std::string& command) {
  const auto start = std::chrono::steady_clock::now();
  if (std::system(command.c_str()) != 0) {
    std::cerr << "failed: " << command << "\n";
    std::exit(1);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && args[0] == "__read-brep") return run_read_brep_child({args.begin() + 1, args.end()});
  if (args.size() == 3 && (args[0] == "in-process" || args[0] == "walled")) {
    CommandContext context;
    context.read_wall = args[0] == "walled";
    return run_convert({args[1], "-o", args[2]}, context);
  }
  const int rounds = args.empty() ? 3 : std::atoi(args[0].c_str());
  std::vector<std::string> files(args.size() > 1 ? args.begin() + 1 : args.end(), args.end());  // default: all
  if (files.empty())
    for (const char* folder : {CADNURBS_SHARED_DIR "/corpus/step", CADNURBS_SHARED_DIR "/corpus/iges"})
      for (const auto& entry : std::filesystem::directory_iterator(folder)) files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  const std::string self = std::filesystem::canonical("/proc/self/exe").string();
  const std::string out = (std::filesystem::temp_directory_path() / "walled_read_overhead.x3dv").string();
  double total_in = 0, total_walled = 0;
  std::cout << "| file | in-process (s) | walled (s) | walled / in-process |\n|---|---:|---:|---:|\n";
  for (const auto& file : files) {
    double best_in = 1e300, best_walled = 1e300;
    for (int round = 0; round < rounds; ++round) {
      // Alternate which goes first, so that neither always finds the file in a warmer cache.
      for (const char* mode : round % 2 ? std::vector{"walled", "in-process"} : std::vector{"in-process", "walled"}) {
        const double t = seconds_of(self + " " + mode + " '" + file + "' " + out + " >/dev/null 2>&1");
        double& best = std::string(mode) == "walled" ? best_walled : best_in;
        best = std::min(best, t);
      }
    }
    total_in += best_in;
    total_walled += best_walled;
    std::cout << "| " << std::filesystem::path(file).filename().string() << " | " << best_in << " | " << best_walled
              << " | " << best_walled / best_in << " |\n";
  }
  std::filesystem::remove(out);
  std::cout << "| total (" << files.size() << " files, fastest of " << rounds << ") | " << total_in << " | " << total_walled
            << " | " << total_walled / total_in << " |\n";
}
