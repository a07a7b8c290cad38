#pragma once
// A part's record (report/storage_record.hpp) from what converting it already knows: the part as read
// (unit, diagonal, its NURBS counts, the reader's repairs and fallen-back faces) and, per file written,
// its bytes raw and gzip'd, what it holds, and the bound on its deviation that the conversion gives.
// `batch` keeps this record for each part unless --measure asks for the report's full comparison
// (part_measurement.hpp), which writes and reads back every representation.
#include <string>

#include "converters/conversion.hpp"
#include "report/storage_record.hpp"

namespace cadnurbs {

// A reader's or writer's one-line message as a record's error: without the "<input>: " it starts with,
// since a record names its input already.
std::string record_error(std::string message, const std::string& input);

// The record of `input` as read (`loaded`): unit, diagonal, the NURBS counts, the repairs and fallbacks
// as warnings; D is convert's default (1e-3 of the diagonal). Throws FileError for a part whose
// coordinates cannot be used (checked_diagonal).
PartRecord conversion_record(const std::string& input, const BrepTranslation& loaded);

// Adds the file convert_loaded wrote at `path` as the representation `key` (batch: the target, "x3dv"):
// its bytes and gzip'd bytes as on disk, the floats and integers of `written` (the scene handed to the
// writer, ConversionLog::written) by the report's accounting, and result's deviation bound and basis.
// Meant to be called from ConversionLog::written, which hands over both.
// A certified mesh also gives the record its mesh figures and certificate.
void add_written_file(PartRecord& record, const std::string& key, const std::string& path, const Scene& written,
                      const ConversionResult& result);

}  // namespace cadnurbs
