#pragma once
// `cadnurbs batch`: a library folder converted part by part, each part in its own worker process under
// limits, with a JSON record per part and a combined report; resumable, and sliceable for a cluster.
#include <optional>
#include <string>
#include <vector>

#include "converters/batch/write_site.hpp"
#include "converters/file_formats.hpp"

namespace cadnurbs {

struct BatchOptions {
  std::string in_dir, out_dir;
  int jobs = 1;                              // workers at a time
  std::vector<std::string> targets{"x3dv"};  // output extensions, each written as OUT_DIR/<part>.<ext>
  std::vector<const FileFormat*> inputs;     // only parts of these formats (library_listing.hpp); empty: all
  // The record: false, what converting the part already knows (conversion_record.hpp); true, the
  // report's full comparison of representations (part_measurement.hpp) at D = deviation_mm.
  bool measure = false;
  double deviation_mm = 1.0;                 // D of --measure's meshes (the report's default)
  double seconds = 300;                      // per part: wall and CPU time
  long megabytes = 4096;                     // per part: address space
  int shard = 0, shards = 1;                 // this run's slice of the library (library_listing.hpp)
  bool progress_bar = false;                 // a progress line redrawn in place (stderr is a terminal)
  SceneReadOptions read;                     // how parts are read (the STEP/IGES wall: when the executable has one)
  std::string site_dir;                      // when not empty, the library as a static site (write_site.hpp);
                                             // needs "cnb" among the targets
};

// What the options that shape a part's results come to, as records keep it: a record made with other
// targets or another D is not reused.
std::string options_key(const BatchOptions& options);

struct BatchSummary {
  int parts = 0;      // in this run's slice
  int converted = 0;  // done in this run
  int reused = 0;     // records already there for the same content and options
  int failed = 0;     // of all parts in the slice, whether done now or before
  std::optional<SiteSummary> site;  // what the site weighs, when one was asked for
};

// Runs the batch (the caller must run one thread: workers are forks). Per part: OUT_DIR/<part>.<target>
// for each target and OUT_DIR/<part>.json (batch_record.hpp), the record last, atomically. Logs one line
// per part to stderr. Ends with the combined report of the slice: OUT_DIR/report.md, report.json,
// report.csv, report.html (with shards > 1: report-<shard>-of-<shards>.*), then the site when asked for.
// Throws FileError when IN_DIR cannot be listed or OUT_DIR or the site not made.
BatchSummary convert_library(const BatchOptions& options);

// The combined report of every record under OUT_DIR (all shards'), written as OUT_DIR/report.md,
// report.json, report.csv, report.html; returns the number of parts and of failed ones.
BatchSummary merge_batch(const std::string& out_dir);

}  // namespace cadnurbs
