#include "formats/cnb/cnb_container.hpp"

#include <zlib.h>

#include <stdexcept>
#include <utility>

#include "formats/cnb/adaptive_arithmetic_coder.hpp"
#include "formats/cnb/cnb_coder_prior.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs::cnb {

namespace {

constexpr char magic[4] = {'\x89', 'C', 'N', 'B'};
constexpr uint8_t deflate_id = 1;
// Raw deflate cannot expand more than 1032:1.
constexpr size_t deflate_expansion_limit = 1032;

// The arithmetic coders: the header's coder byte, the first version that knows it, where its models
// start and how they adapt.
struct ArithmeticCoder {
  CnbOptions::Coder coder;
  uint8_t id;
  uint8_t first_version;
  const ContextModels& (*start)(uint8_t version);
  Adaptation adaptation;
};
const ContextModels& uniform_start(uint8_t) {
  static const ContextModels models = uniform_models();
  return models;
}
constexpr ArithmeticCoder arithmetic_coders[] = {
    {CnbOptions::Coder::arithmetic, 2, 1, uniform_start, Adaptation::one_rate},
    {CnbOptions::Coder::arithmetic_prior, 3, 4, coder_prior_models, Adaptation::one_rate},
    {CnbOptions::Coder::arithmetic_two_rates, 4, 7, coder_prior_models, Adaptation::two_rates},
};

void put_u32(std::string& s, uint32_t v) {
  for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>(v >> (8 * i)));
}
uint32_t get_u32(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(static_cast<uint8_t>(s[at + i])) << (8 * i);
  return v;
}

uint32_t crc(const std::string& s, size_t from, size_t count, uint32_t start = 0) {
  uLong c = start ? start : crc32(0L, Z_NULL, 0);
  c = crc32(c, reinterpret_cast<const Bytef*>(s.data() + from), static_cast<uInt>(count));
  return static_cast<uint32_t>(c);
}

std::string deflate_raw(const std::string& bytes) {
  z_stream z{};
  if (deflateInit2(&z, 9, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK) throw std::runtime_error("cnb: deflateInit2 failed");
  std::string out(deflateBound(&z, bytes.size()), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (status != Z_STREAM_END) throw std::runtime_error("cnb: deflate failed");
  return out;
}

[[noreturn]] void refuse(const std::string& name, size_t at, const std::string& reason) {
  throw FileError(name + ": byte " + std::to_string(at) + ": " + reason);
}

class OwnedBufferSource : public ByteSource {
 public:
  explicit OwnedBufferSource(std::string bytes) : bytes_(std::move(bytes)) {}
  uint8_t next(int) override { return static_cast<uint8_t>(bytes_[position_++]); }

 private:
  std::string bytes_;
  size_t position_ = 0;
};

class OwnedArithmeticSource : public ByteSource {
 public:
  OwnedArithmeticSource(std::string coded, const ArithmeticCoder& coder, uint8_t version)
      : coded_(std::move(coded)), decoder_(coded_.data(), coded_.size(), coder.start(version), coder.adaptation) {}
  uint8_t next(int context) override { return decoder_.next(context); }

 private:
  std::string coded_;
  ArithmeticDecoder decoder_;
};

// The payload of `size` bytes deflated in `file` from byte `start` to the end.
std::string inflate_raw(const std::string& file, size_t start, size_t size, const std::string& name) {
  std::string out(size, '\0');
  z_stream z{};
  if (inflateInit2(&z, -15) != Z_OK) throw std::runtime_error("cnb: inflateInit2 failed");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(file.data() + start));
  z.avail_in = static_cast<uInt>(file.size() - start);
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  int status = inflate(&z, Z_FINISH);
  // The buffer is full but the stream goes on: one more byte of room tells a stream that holds more than
  // the header says from one that only has its end marker left.
  bool more = false;
  if (status != Z_STREAM_END && z.avail_out == 0) {
    unsigned char extra = 0;
    z.next_out = &extra;
    z.avail_out = 1;
    status = inflate(&z, Z_FINISH);
    more = z.avail_out == 0;
  }
  const size_t produced = z.total_out, consumed = z.total_in;
  const std::string message = z.msg ? z.msg : "";
  inflateEnd(&z);
  if (more)
    refuse(name, 6, "the deflate stream holds more than the " + std::to_string(size) + " payload bytes the header promises");
  if (status == Z_STREAM_END && produced == size && consumed == file.size() - start) return out;
  if (status == Z_STREAM_END && produced < size)
    refuse(name, 6, "the header promises " + std::to_string(size) + " payload bytes, the deflate stream holds " + std::to_string(produced));
  if (status == Z_STREAM_END)
    refuse(name, start + consumed, "bytes after the end of the deflate stream");
  refuse(name, start + consumed, "damaged deflate stream" + (message.empty() ? std::string() : " (" + message + ")"));
}

}  // namespace

std::string pack(const ByteWriter& payload, CnbOptions::Coder choice, CnbWriteReport* report, uint8_t version) {
  if (payload.bytes().size() > 0xFFFFFFFFu) throw std::runtime_error("cnb: a payload above 4 GiB");
  // The entropy coders, each tried when asked for by name or for the smallest; ties keep the earlier.
  struct Candidate {
    CnbOptions::Coder coder;
    uint8_t id;
    std::string coded;
  };
  std::vector<Candidate> candidates = {{CnbOptions::Coder::deflate, deflate_id, {}}};
  for (const ArithmeticCoder& a : arithmetic_coders) candidates.push_back({a.coder, a.id, {}});
  const Candidate* chosen = nullptr;
  for (size_t i = 0; i < candidates.size(); ++i) {
    Candidate& c = candidates[i];
    if (choice != CnbOptions::Coder::smallest && choice != c.coder) continue;
    c.coded = i == 0 ? deflate_raw(payload.bytes())
                     : arithmetic_encode(payload.bytes(), payload.contexts(), arithmetic_coders[i - 1].start(version),
                                         arithmetic_coders[i - 1].adaptation);
    if (!chosen || c.coded.size() < chosen->coded.size()) chosen = &c;
  }
  const std::string& coded = chosen->coded;
  const uint8_t id = chosen->id;
  std::string file(magic, 4);
  file.push_back(static_cast<char>(version));
  file.push_back(static_cast<char>(id));
  for (uint64_t v = payload.bytes().size();; v >>= 7) {
    file.push_back(static_cast<char>((v & 0x7F) | (v >= 0x80 ? 0x80 : 0)));
    if (v < 0x80) break;
  }
  // The CRC covers the header before it and the coded payload.
  put_u32(file, crc(coded, 0, coded.size(), crc(file, 0, file.size())));
  file += coded;
  if (report) {
    report->payload_bytes = payload.bytes().size();
    report->deflate_bytes = candidates[0].coded.size();
    report->arithmetic_bytes = candidates[1].coded.size();
    report->arithmetic_prior_bytes = candidates[2].coded.size();
    report->arithmetic_two_rates_bytes = candidates[3].coded.size();
    report->file_bytes = file.size();
  }
  return file;
}

namespace {

// Where the coded bytes start and how many payload bytes they promise, with the CRC checked: version 1's
// fixed header.
std::pair<size_t, size_t> version_1_header(const std::string& file, const std::string& name) {
  constexpr size_t h = version_1_header_size;
  if (file.size() < h)
    refuse(name, file.size(), "truncated: the header needs " + std::to_string(h) + " bytes, the file has " + std::to_string(file.size()));
  const size_t size = get_u32(file, 6), coded = get_u32(file, 10);
  if (file.size() - h != coded)
    refuse(name, std::min(file.size(), h + coded),
           (file.size() - h < coded ? "truncated: the header promises " : "damaged: the header promises ") +
               std::to_string(coded) + " coded bytes after byte " + std::to_string(h) + ", the file has " +
               std::to_string(file.size() - h));
  if (crc(file, h, coded, crc(file, 0, 14)) != get_u32(file, 14))
    refuse(name, 14, "damaged: the CRC-32 of the file does not match the one in its header");
  return {h, size};
}

// The same for versions 2 to 6: the payload size as a varuint at byte 6, then the CRC of all before it and of
// the coded bytes, which run to the end of the file.
std::pair<size_t, size_t> version_2_header(const std::string& file, const std::string& name) {
  uint64_t size = 0;
  size_t at = 6;
  for (int shift = 0;; shift += 7, ++at) {
    if (at >= file.size()) refuse(name, file.size(), "truncated: the file ends inside the header");
    const uint8_t b = static_cast<uint8_t>(file[at]);
    size |= static_cast<uint64_t>(b & 0x7F) << shift;
    if (!(b & 0x80)) break;
    if (shift == 28) refuse(name, 6, "damaged: the payload size is longer than 5 bytes");
  }
  const size_t crc_at = at + 1;
  if (size > 0xFFFFFFFFu) refuse(name, 6, "damaged: a payload size above 4 GiB");
  if (file.size() < crc_at + 4) refuse(name, file.size(), "truncated: the file ends inside the header");
  if (crc(file, crc_at + 4, file.size() - crc_at - 4, crc(file, 0, crc_at)) != get_u32(file, crc_at))
    refuse(name, crc_at, "damaged or truncated: the CRC-32 of the file does not match the one in its header");
  return {crc_at + 4, static_cast<size_t>(size)};
}

}  // namespace

OpenedPayload open_payload(const std::string& file, const std::string& name) {
  for (size_t i = 0; i < 4; ++i) {
    if (i >= file.size()) refuse(name, file.size(), "truncated: the file ends inside the magic number");
    if (file[i] != magic[i]) refuse(name, i, "not a .cnb file (the magic number is \\x89CNB)");
  }
  if (file.size() < 6) refuse(name, file.size(), "truncated: the file ends inside the header");
  const uint8_t version = static_cast<uint8_t>(file[4]);
  if (version < 1 || version > format_version)
    refuse(name, 4, "version " + std::to_string(version) + " is not one this reader knows (1 to " +
                        std::to_string(format_version) + ")");
  const auto [start, size] = version == 1 ? version_1_header(file, name) : version_2_header(file, name);
  const size_t coded = file.size() - start;
  const uint8_t id = static_cast<uint8_t>(file[5]);
  OpenedPayload opened;
  opened.size = size;
  opened.version = version;
  if (id == deflate_id) {
    if (size > deflate_expansion_limit * coded + 64) refuse(name, 6, "a payload of " + std::to_string(size) + " bytes cannot come from " + std::to_string(coded) + " deflated bytes");
    opened.source = std::make_unique<OwnedBufferSource>(inflate_raw(file, start, size, name));
  } else {
    const ArithmeticCoder* coder = nullptr;
    for (const ArithmeticCoder& a : arithmetic_coders)
      if (a.id == id && version >= a.first_version) coder = &a;
    if (!coder) refuse(name, 5, "unknown entropy coder " + std::to_string(id));
    if (size > arithmetic_expansion_limit(coder->adaptation) * coded + 64) refuse(name, 6, "a payload of " + std::to_string(size) + " bytes cannot come from " + std::to_string(coded) + " coded bytes");
    opened.source = std::make_unique<OwnedArithmeticSource>(file.substr(start), *coder, version);
    opened.arithmetic = true;
  }
  return opened;
}

}  // namespace cadnurbs::cnb
