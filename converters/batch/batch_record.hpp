#pragma once
// A batch part's record on disk: the report's part record (docs/report.md) plus what the batch needs to
// resume and to account for the run: the part's name in the library, its content hash, the options it
// was made with, how long it took. One file OUT_DIR/<part>.json, written atomically after the part's
// outputs, so that a record on disk means the part is done.
#include <optional>
#include <string>

#include "report/storage_record.hpp"

namespace cadnurbs {

struct BatchFields {
  std::string part;        // the part's path under IN_DIR ('/'-separated)
  std::string input_hash;  // content_hash of the input when it was done
  std::string options;     // the options key it was done with (batch_options.hpp)
  double seconds = 0;      // wall time of its worker
};

// "crc32:<8 hex>/adler32:<8 hex>/<size>" of a file's bytes (zlib's checksums, read in blocks): what tells a
// changed input from the one a record was made of. Throws FileError when the file cannot be read.
std::string content_hash(const std::string& path);

// The record's text: part_record_json's object with a "batch" object added.
std::string batch_record_json(const PartRecord& record, const BatchFields& fields);

struct BatchRecord {
  PartRecord record;
  BatchFields fields;
};

// Whether the record is of a part that failed by exceeding a time or memory limit (its error begins
// "exceeded "): a result of the machine and its load as much as of the part, so a rerun does it again,
// where a part that failed for its content keeps its record.
bool failed_by_a_limit(const PartRecord& record);

// The record in the file at `path`, or nothing when there is none or it cannot be parsed (a record
// that cannot be read counts as not done).
std::optional<BatchRecord> read_batch_record(const std::string& path);

}  // namespace cadnurbs
