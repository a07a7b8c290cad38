#pragma once
// Reading back what part_record_json (report_formats.hpp) writes, so that records written one part at a
// time (report --records, batch) can be laid out together later (batch --merge, a resumed batch).
#include <string>

#include "report/storage_record.hpp"

namespace cadnurbs {

// Takes the text of one JSON record and a name for messages. Returns the PartRecord it holds: every field
// part_record_json writes, as record_fields.hpp describes them (a null deviation is NaN; derived totals such
// as total_floats are not read, they are computed). Throws std::invalid_argument "<name>: not a part record
// (<reason>)" for text that is not JSON or lacks a field.
PartRecord part_record_from_json(const std::string& text, const std::string& name);

}  // namespace cadnurbs
