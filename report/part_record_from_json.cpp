#include "report/part_record_from_json.hpp"

#include <stdexcept>

#include "report/record_fields.hpp"

namespace cadnurbs {

namespace {

// The status says which fields follow: a failed part's error or a measured part's figures.
PartRecord record_from(const ReadJson& j) {
  PartRecord r;
  read_json_fields(part_status_fields(), j, r);
  read_json_fields(part_outcome_fields(r), j, r);
  return r;
}

}  // namespace

PartRecord part_record_from_json(const std::string& text, const std::string& name) {
  try {
    return record_from(ReadJson::parse(text));
  } catch (const std::exception& error) {
    throw std::invalid_argument(name + ": not a part record (" + error.what() + ")");
  }
}

}  // namespace cadnurbs
