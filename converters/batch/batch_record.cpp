#include "converters/batch/batch_record.hpp"

#include <zlib.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "report/part_record_from_json.hpp"
#include "report/record_fields.hpp"
#include "report/report_formats.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

// What a batch record adds to the part record's fields: one object, "batch".
const JsonFields<BatchFields>& batch_record_fields() {
  static const JsonFields<BatchFields> fields{group_field<BatchFields>(
      "batch", {value_field("part", &BatchFields::part), value_field("input_hash", &BatchFields::input_hash),
                value_field("options", &BatchFields::options), value_field("seconds", &BatchFields::seconds)})};
  return fields;
}

}  // namespace

std::string content_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path + ": cannot be read");
  uLong crc = crc32(0L, Z_NULL, 0), adler = adler32(0L, Z_NULL, 0);
  unsigned long long size = 0;
  std::vector<char> block(1 << 16);
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const auto n = static_cast<uInt>(in.gcount());
    crc = crc32(crc, reinterpret_cast<const Bytef*>(block.data()), n);
    adler = adler32(adler, reinterpret_cast<const Bytef*>(block.data()), n);
    size += n;
  }
  char text[80];
  std::snprintf(text, sizeof text, "crc32:%08lx/adler32:%08lx/%llu", crc, adler, size);
  return text;
}

std::string batch_record_json(const PartRecord& record, const BatchFields& fields) {
  WrittenJson j = WrittenJson::parse(part_record_json(record));
  write_json_fields(batch_record_fields(), fields, j);
  return j.dump(2) + "\n";
}

std::optional<BatchRecord> read_batch_record(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  try {
    BatchRecord r;
    read_json_fields(batch_record_fields(), ReadJson::parse(text.str()), r.fields);
    r.record = part_record_from_json(text.str(), path);
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

bool failed_by_a_limit(const PartRecord& record) { return record.failed && record.error.rfind("exceeded ", 0) == 0; }

}  // namespace cadnurbs
