#include "converters/batch/convert_library.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "report/html/library_report_html.hpp"
#include "report/report_formats.hpp"
#include "converters/batch/batch_record.hpp"
#include "converters/batch/library_listing.hpp"
#include "converters/batch/warm_parent.hpp"
#include "converters/batch/worker_pool.hpp"
#include "converters/conversion.hpp"
#include "converters/conversion_record.hpp"
#include "converters/part_measurement.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

std::string record_path(const fs::path& stem) { return stem.string() + ".json"; }

PartRecord failed_record(const std::string& part, const std::string& error) {
  PartRecord record;
  record.input = part;
  record.failed = true;
  record.error = error;
  return record;
}

// The part's file, as the worker reads it.
std::string input_path(const BatchOptions& options, const LibraryPart& part) {
  return (fs::path(options.in_dir) / part.relative).string();
}

// The part's outputs, removed when the part fails: a failed part leaves its record only.
void remove_outputs(const BatchOptions& options, const fs::path& stem) {
  std::error_code ignored;
  for (const auto& target : options.targets) fs::remove(stem.string() + "." + target, ignored);
}

// The worker's work for one part: the part read once, then each output written from it, each as
// `convert INPUT -o OUT` would write it, then the record on disk: what the conversions knew
// (conversion_record.hpp), or with --measure the report's full comparison (part_measurement.hpp).
int run_part(const BatchOptions& options, const LibraryPart& part, const fs::path& stem) {
  const auto start = Clock::now();
  const std::string input = input_path(options, part);
  ConversionRequest request;  // convert's defaults
  request.input = input;
  // The STEP/IGES wall inside the worker stops a little before the worker is killed, naming the stage.
  request.read = options.read;
  request.read.brep.limits = {0.9 * options.seconds, options.megabytes};
  if (part.by_content) request.input_format = part.format;
  PartRecord record;
  try {
    const LoadedInput loaded = load_input(request);
    if (options.measure) {
      PartMeasurementOptions measurement;
      measurement.deviation_mm = options.deviation_mm;
      measurement.read = request.read;
      record = measure_loaded_part(input, loaded.loaded, measurement);
    } else {
      record = conversion_record(input, loaded.loaded);
    }
    fs::create_directories(stem.parent_path());
    for (const auto& target : options.targets) {
      if (record.failed) break;
      request.output = stem.string() + "." + target;
      ConversionLog log;
      if (!options.measure)
        log.written = [&](const Scene& written, const ConversionResult& result) {
          add_written_file(record, target, request.output, written, result);
        };
      convert_loaded(request, loaded, log);
    }
  } catch (const std::exception& error) {
    record = failed_record(part.relative, record_error(error.what(), input));
  }
  if (record.failed) remove_outputs(options, stem);
  record.input = part.relative;
  const BatchFields fields{part.relative, content_hash(input), options_key(options),
                           std::chrono::duration<double>(Clock::now() - start).count()};
  write_file_atomically(record_path(stem), batch_record_json(record, fields));
  return 0;
}

// The record a worker that ended badly leaves: the reason, on disk like any other.
PartRecord record_failure(const BatchOptions& options, const LibraryPart& part, const fs::path& stem,
                          const std::string& reason, double seconds) {
  const std::string input = input_path(options, part);
  PartRecord record = failed_record(part.relative, reason);
  remove_outputs(options, stem);
  std::string hash;
  try {
    hash = content_hash(input);
  } catch (const FileError&) {
  }
  try {
    fs::create_directories(stem.parent_path());
    write_file_atomically(record_path(stem), batch_record_json(record, {part.relative, hash, options_key(options), seconds}));
  } catch (const std::exception& error) {
    // The part stays in this run's report; a rerun does it again. The batch itself goes on.
    std::cerr << "batch: " << part.relative << ": its record cannot be written: " << error.what() << "\n";
  }
  return record;
}

void write_reports(const fs::path& out_dir, const std::string& name, const std::vector<PartRecord>& records) {
  write_file_atomically((out_dir / (name + ".md")).string(), report_markdown(records));
  write_file_atomically((out_dir / (name + ".json")).string(), report_json(records));
  write_file_atomically((out_dir / (name + ".csv")).string(), report_csv(records));
  write_file_atomically((out_dir / (name + ".html")).string(), library_report_html(records));
}

// Tenths of a second, like the progress line's parts per minute: a fixed number of decimals, which
// number_text's significant digits cannot give ("12.0 s", "1234.5 s").
std::string seconds_text(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", s);
  return text;
}

}  // namespace

std::string options_key(const BatchOptions& options) {
  std::ostringstream key;
  key << "to=";
  for (size_t i = 0; i < options.targets.size(); ++i) key << (i ? "," : "") << options.targets[i];
  if (options.measure)
    key << ";measure;deviation_mm=" << options.deviation_mm;
  else
    key << ";record=conversion";
  return key.str();
}

BatchSummary convert_library(const BatchOptions& options) {
  const std::vector<LibraryPart> parts = shard_of(of_formats(list_library(options.in_dir), options.inputs), options.shard, options.shards);
  std::error_code error;
  fs::create_directories(options.out_dir, error);
  if (error || !fs::is_directory(options.out_dir)) throw FileError(options.out_dir + ": cannot be made a folder");
  const std::string key = options_key(options);
  BatchSummary summary;
  summary.parts = static_cast<int>(parts.size());
  std::vector<std::optional<PartRecord>> results(parts.size());
  std::vector<fs::path> stems(parts.size());
  std::vector<size_t> to_convert;
  int finished = 0, failed = 0;
  const auto started = Clock::now();
  // On a terminal: one line redrawn in place (count, failures, rate, ETA), failures kept above it. Else
  // one log line per part.
  auto log = [&](size_t i, const PartRecord& record, const std::string& how) {
    ++finished;
    failed += record.failed ? 1 : 0;
    const std::string line = "batch: [" + std::to_string(finished) + "/" + std::to_string(parts.size()) + "] " +
                             parts[i].relative + ": " + (record.failed ? "failed: " + record.error : how);
    if (!options.progress_bar) {
      std::cerr << line << "\n";
      return;
    }
    const double minutes = std::chrono::duration<double>(Clock::now() - started).count() / 60;
    const double rate = minutes > 0 ? finished / minutes : 0;
    const int left = static_cast<int>(parts.size()) - finished;
    const int eta = rate > 0 ? static_cast<int>(60 * left / rate) : 0;
    const int width = 30, filled = static_cast<int>(width * finished / std::max<size_t>(1, parts.size()));
    char status[160];
    std::snprintf(status, sizeof status, "\r[%s%s] %d/%zu parts, %d failed, %.1f parts/min, ETA %d:%02d:%02d ",
                  std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(), finished, parts.size(),
                  failed, rate, eta / 3600, eta / 60 % 60, eta % 60);
    if (record.failed) std::cerr << "\r\033[K" << line << "\n";
    std::cerr << status << (finished == static_cast<int>(parts.size()) ? "\n" : "") << std::flush;
  };
  for (size_t i = 0; i < parts.size(); ++i) {
    const LibraryPart& part = parts[i];
    try {
      stems[i] = output_stem(options.out_dir, part.relative);
    } catch (const std::invalid_argument& refused) {
      results[i] = failed_record(part.relative, std::string("refused: ") + refused.what());
      log(i, *results[i], "");
      continue;
    }
    if (!part.refusal.empty()) {
      results[i] = record_failure(options, part, stems[i], "refused: it " + part.refusal, 0);
      log(i, *results[i], "");
      continue;
    }
    const std::string input = input_path(options, part);
    if (const auto done = read_batch_record(record_path(stems[i]))) {
      std::string hash;
      try {
        hash = content_hash(input);
      } catch (const FileError&) {
      }
      if (done->fields.options == key && done->fields.input_hash == hash && done->fields.part == part.relative &&
          !failed_by_a_limit(done->record)) {
        results[i] = done->record;
        ++summary.reused;
        log(i, *results[i], "done before");
        continue;
      }
    }
    to_convert.push_back(i);
  }
  const ProcessLimits limits{options.seconds, options.megabytes};
  if (!to_convert.empty()) warm_up_readers();
  run_in_workers(
      static_cast<int>(to_convert.size()), options.jobs, limits,
      [&](int k) { return run_part(options, parts[to_convert[k]], stems[to_convert[k]]); },
      [&](int k, const WorkerOutcome& outcome) {
        const size_t i = to_convert[k];
        std::string reason = outcome.reason(limits);
        std::optional<BatchRecord> written;
        if (reason.empty() && !(written = read_batch_record(record_path(stems[i])))) reason = "the worker left no record";
        results[i] = reason.empty() ? written->record : record_failure(options, parts[i], stems[i], reason, outcome.seconds);
        ++summary.converted;
        log(i, *results[i], "ok, " + seconds_text(outcome.seconds));
      });
  std::vector<PartRecord> records;
  for (auto& result : results) {
    if (result->failed) ++summary.failed;
    records.push_back(std::move(*result));
  }
  const std::string name = options.shards > 1 ? "report-" + std::to_string(options.shard) + "-of-" + std::to_string(options.shards)
                                              : "report";
  write_reports(options.out_dir, name, records);
  if (!options.site_dir.empty())
    summary.site = write_site({options.in_dir, options.out_dir, options.site_dir, options.jobs, limits}, parts, records);
  return summary;
}

BatchSummary merge_batch(const std::string& out_dir) {
  std::error_code error;
  if (!fs::is_directory(out_dir, error)) throw FileError(out_dir + ": not a folder");
  std::vector<BatchRecord> found;
  for (fs::recursive_directory_iterator walk(out_dir, error), end; !error && walk != end; walk.increment(error))
    if (walk->is_regular_file() && walk->path().extension() == ".json")
      if (auto record = read_batch_record(walk->path().string())) found.push_back(std::move(*record));
  if (error) throw FileError(out_dir + ": cannot be walked (" + error.message() + ")");
  std::sort(found.begin(), found.end(), [](const BatchRecord& a, const BatchRecord& b) { return a.fields.part < b.fields.part; });
  BatchSummary summary;
  std::vector<PartRecord> records;
  for (auto& r : found) {
    ++summary.parts;
    if (r.record.failed) ++summary.failed;
    records.push_back(std::move(r.record));
  }
  write_reports(out_dir, "report", records);
  return summary;
}

}  // namespace cadnurbs
