// Part 21 parse speed (issue 37): parse_part21 (the native reader's parser, building the entity table)
// against precheck_step (the lexical pre-check, no table) over the same STEP files, side by side in one
// run. Each file is read into memory once (reading is not timed), then each pass runs ROUNDS times
// alternately; a file's time per pass is its fastest round. Also checks that both see the same instance
// and reference counts. `part21_parse_speed [ROUNDS] DIR_OR_FILE...`: STEP files found under the folders
// (recursively, .step/.stp), e.g. ~/.cache/cadnurbs/kicad-packages3d-6.0.10-1.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "formats/common/file_io.hpp"
#include "formats/step/part21/parse_part21.hpp"
#include "formats/step/step_precheck.hpp"

using namespace cadnurbs;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::vector<std::string> step_files(const std::vector<std::string>& arguments) {
  std::vector<std::string> files;
  for (const std::string& argument : arguments) {
    if (std::filesystem::is_regular_file(argument)) {
      files.push_back(argument);
      continue;
    }
    for (const auto& entry : std::filesystem::recursive_directory_iterator(argument)) {
      const std::string extension = file_extension(entry.path().string());
      if (entry.is_regular_file() && (extension == ".step" || extension == ".stp")) files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> arguments(argv + 1, argv + argc);
  int rounds = 3;
  if (!arguments.empty() && std::all_of(arguments[0].begin(), arguments[0].end(), ::isdigit)) {
    rounds = std::stoi(arguments[0]);
    arguments.erase(arguments.begin());
  }
  if (arguments.empty()) {
    std::fprintf(stderr, "usage: part21_parse_speed [ROUNDS] DIR_OR_FILE...\n");
    return 2;
  }
  const std::vector<std::string> files = step_files(arguments);
  double bytes = 0, precheck_seconds = 0, parse_seconds = 0;
  std::size_t entities = 0, refused = 0, mismatched = 0;
  for (const std::string& path : files) {
    const std::string content = read_file(path);
    double precheck_best = 1e30, parse_best = 1e30;
    StepPrecheckFigures figures;
    std::size_t parsed_entities = 0, parsed_references = 0;
    try {
      for (int round = 0; round < rounds; ++round) {
        double start = now();
        figures = precheck_step(content, path);
        precheck_best = std::min(precheck_best, now() - start);
        start = now();
        const part21::Model model = part21::parse_part21(content, path);
        parse_best = std::min(parse_best, now() - start);
        parsed_entities = model.size();
        parsed_references = model.reference_count();
      }
    } catch (const FileError& error) {
      std::printf("refused: %s\n", error.what());
      ++refused;
      continue;
    }
    if (parsed_entities != figures.entities || parsed_references != figures.references) {
      std::printf("counts differ: %s: %zu/%zu instances, %zu/%zu references (parse/precheck)\n", path.c_str(),
                  parsed_entities, figures.entities, parsed_references, figures.references);
      ++mismatched;
    }
    bytes += static_cast<double>(content.size());
    precheck_seconds += precheck_best;
    parse_seconds += parse_best;
    entities += parsed_entities;
  }
  const double megabytes = bytes / 1e6;
  std::printf("%zu files, %.1f MB, %zu instances; %zu refused, %zu with other counts; best of %d rounds per file\n",
              files.size(), megabytes, entities, refused, mismatched, rounds);
  std::printf("precheck_step  %7.3f s  %7.1f MB/s\n", precheck_seconds, megabytes / precheck_seconds);
  std::printf("parse_part21   %7.3f s  %7.1f MB/s  (%.2f x the pre-check's time)\n", parse_seconds, megabytes / parse_seconds,
              parse_seconds / precheck_seconds);
  return refused == 0 && mismatched == 0 ? 0 : 1;
}
