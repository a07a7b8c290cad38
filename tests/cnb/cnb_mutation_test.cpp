// Payloads with random bytes changed, packed again with a valid checksum (as a writer with a bug, or an
// attacker, would make them): every one is read or refused with a FileError; nothing else escapes.
#include <gtest/gtest.h>

#include <random>

#include "formats/cnb/cnb_container.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/common/file_io.hpp"
#include "formats/step/step_reader.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

std::string decoded_payload(const std::string& file) {
  cnb::OpenedPayload opened = cnb::open_payload(file, "x.cnb");
  std::string bytes(opened.size, '\0');
  for (char& c : bytes) c = static_cast<char>(opened.source->next(0));
  return bytes;
}

void mutate_and_read(const Scene& scene, unsigned seed, int trials) {
  CnbOptions options;
  options.coder = CnbOptions::Coder::deflate;  // contexts do not matter to deflate
  const std::string payload = decoded_payload(write_cnb(scene, options));
  std::mt19937 random(seed);
  int read = 0, refused = 0;
  for (int trial = 0; trial < trials; ++trial) {
    std::string bytes = payload;
    const int changes = 1 + static_cast<int>(random() % 4);
    for (int c = 0; c < changes; ++c) {
      const size_t at = random() % bytes.size();
      switch (random() % 3) {
        case 0: bytes[at] = static_cast<char>(random()); break;       // any value
        case 1: bytes[at] = static_cast<char>(bytes[at] ^ 0x80); break;  // a varint's continuation bit
        default: bytes.erase(at, 1 + random() % 8); break;             // bytes lost
      }
      if (bytes.empty()) bytes = "x";
    }
    cnb::ByteWriter w;
    for (char b : bytes) w.byte(static_cast<uint8_t>(b));
    try {
      read_cnb(cnb::pack(w, CnbOptions::Coder::deflate, nullptr), "x.cnb");
      ++read;
    } catch (const FileError& e) {
      ASSERT_EQ(std::string(e.what()).rfind("x.cnb: decoded byte ", 0), 0u) << e.what();
      ASSERT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      ++refused;
    }
  }
  EXPECT_GT(refused, trials / 2);
  std::cout << read << " read, " << refused << " refused\n";
}

TEST(CnbMutation, CappingPayloads) {
  mutate_and_read(read_vrml(std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-90.x3dv"), 1, 3000);
}

TEST(CnbMutation, StepPartPayloads) {
  mutate_and_read(read_step(std::string(CADNURBS_SHARED_DIR) + "/corpus/step/dm1-id-214.stp").scene, 2, 1500);
}

}  // namespace
}  // namespace cadnurbs
