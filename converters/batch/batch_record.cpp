#include "converters/batch/batch_record.hpp"

#include <zlib.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "analysis/report/part_record_from_json.hpp"
#include "analysis/report/report_formats.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

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
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(part_record_json(record));
  j["batch"] = {{"part", fields.part}, {"input_hash", fields.input_hash}, {"options", fields.options},
                {"seconds", fields.seconds}};
  return j.dump(2) + "\n";
}

std::optional<BatchRecord> read_batch_record(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  try {
    const nlohmann::json j = nlohmann::json::parse(text.str());
    const nlohmann::json& batch = j.at("batch");
    BatchRecord r;
    r.record = part_record_from_json(text.str(), path);
    r.fields.part = batch.at("part").get<std::string>();
    r.fields.input_hash = batch.at("input_hash").get<std::string>();
    r.fields.options = batch.at("options").get<std::string>();
    r.fields.seconds = batch.at("seconds").get<double>();
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

bool failed_by_a_limit(const PartRecord& record) { return record.failed && record.error.rfind("exceeded ", 0) == 0; }

}  // namespace cadnurbs
