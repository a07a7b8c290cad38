// Damaged, truncated, empty and foreign files give one-line FileErrors naming the file, never a crash;
// a failed write leaves nothing behind.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "corpus_manifest.hpp"
#include "formats/common/file_io.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/iges/iges_writer.hpp"
#include "formats/step/step_reader.hpp"
#include "formats/step/step_writer.hpp"
#include "samples/capping_shapes.hpp"
#include "temporary_folder.hpp"

namespace cadnurbs::test {
namespace {

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

BrepTranslation read_any(const std::string& path) {
  return path.size() > 5 && path.substr(path.size() - 5) == ".step" ? read_step(path) : read_iges(path);
}

// The FileError `read` throws for `path`: one line starting with "<path>: ".
std::string read_error(const std::string& path) {
  try {
    read_any(path);
  } catch (const FileError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << path << " was read without error";
  return {};
}

struct Source {
  const char* corpus;     // a good file
  const char* extension;  // of the damaged copies
};

void PrintTo(const Source& source, std::ostream* out) { *out << source.corpus << " as " << source.extension; }

class DamagedFile : public ::testing::TestWithParam<Source> {
 protected:
  std::string original() const { return read_file(corpus_file(GetParam().corpus)); }
  std::string path(const std::string& stem) const { return folder_.file(stem + GetParam().extension); }
  TemporaryFolder folder_;
};

TEST_P(DamagedFile, EmptyMissingAndForeignFilesAreRefused) {
  const std::string empty = path("empty");
  write_bytes(empty, "");
  EXPECT_EQ(read_error(empty), empty + ": empty file");

  const std::string missing = path("missing");
  EXPECT_EQ(read_error(missing).rfind(missing + ": cannot open (", 0), 0u);

  const std::string text = path("notes");
  write_bytes(text, "These are meeting notes, not geometry.\nSecond line.\n");
  const std::string message = read_error(text);
  EXPECT_NE(message.find(std::string(": not a") + (GetParam().extension == std::string(".step") ? " STEP" : "n IGES")),
            std::string::npos)
      << message;
}

TEST_P(DamagedFile, TruncatedFilesAreRefused) {
  const std::string bytes = original();
  for (double fraction : {0.1, 0.5, 0.9, 0.999}) {
    const std::string cut = path("cut-" + std::to_string(static_cast<int>(fraction * 1000)));
    write_bytes(cut, bytes.substr(0, static_cast<size_t>(fraction * bytes.size())));
    const std::string message = read_error(cut);
    EXPECT_NE(message.find("truncated"), std::string::npos) << message;
  }
}

TEST_P(DamagedFile, CutBodyWithIntactEndIsRefusedNamingAnEntity) {
  // Half the file, then a well-formed end: the framing passes, the missing entities do not.
  const std::string bytes = original();
  std::string head = bytes.substr(0, bytes.size() / 2);
  head.erase(head.find_last_of('\n') + 1);
  std::string damaged;
  if (GetParam().extension == std::string(".step")) {
    damaged = head + "ENDSEC;\nEND-ISO-10303-21;\n";
  } else {
    // IGES: keep the whole directory, drop the second half of the parameter section.
    damaged = head;
    const std::string terminate = bytes.substr(bytes.find_last_of('\n', bytes.size() - 2) + 1);
    damaged += terminate;
  }
  const std::string file = path("cut-body");
  write_bytes(file, damaged);
  const std::string message = read_error(file);
  std::printf("%s\n", message.c_str());
  // Entities referring to missing ones, or, where the first half refers only backwards, no product left.
  if (GetParam().extension == std::string(".step"))
    EXPECT_TRUE(message.find("which the file lacks") != std::string::npos ||
                message.find("no shape in the file") != std::string::npos)
        << message;
  else
    EXPECT_NE(message.find("IGES file is damaged: its Terminate section counts"), std::string::npos) << message;
}

TEST_P(DamagedFile, FlippedBytesNeverCrash) {
  const std::string bytes = original();
  for (unsigned seed = 1; seed <= 6; ++seed) {
    std::string damaged = bytes;
    std::mt19937 rng(seed);
    // Flip bytes away from the first and last kilobyte, so the damage reaches OCCT's parser.
    std::uniform_int_distribution<size_t> where(1024, bytes.size() - 1024);
    for (int i = 0; i < 50 * static_cast<int>(seed); ++i) damaged[where(rng)] ^= static_cast<char>(1 + rng() % 255);
    const std::string file = path("flipped-" + std::to_string(seed));
    write_bytes(file, damaged);
    try {
      const BrepTranslation t = read_any(file);
      std::printf("%s: read, %d faces, %zu fallbacks\n", file.c_str(), t.face_count, t.fallbacks.size());
    } catch (const FileError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(file + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      std::printf("%s\n", message.c_str());
    }
  }
}

std::string source_name(const ::testing::TestParamInfo<Source>& info) {
  std::string out;
  for (const char* c = info.param.corpus; *c; ++c) out += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
  return out;
}

INSTANTIATE_TEST_SUITE_P(Corpus, DamagedFile,
                         ::testing::Values(Source{"step/io1-cm-214.stp", ".step"}, Source{"step/as1-oc-214.stp", ".step"},
                                           Source{"iges/wing.iges", ".igs"}, Source{"iges/Cube_10x10.igs", ".igs"}),
                         source_name);

TEST(FailedWrite, LeavesNothingBehind) {
  TemporaryFolder folder;
  const Scene scene = capping_nurbs(bundled_capping("capping-90"));
  for (const std::string name : {"capping.step", "capping.igs"}) {
    const std::string path = folder.file("no-such-folder/" + name);
    try {
      name == "capping.step" ? write_step(path, scene) : write_iges(path, scene);
      ADD_FAILURE() << "wrote " << path;
    } catch (const FileError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  EXPECT_TRUE(std::filesystem::is_empty(folder.path()));
}

}  // namespace
}  // namespace cadnurbs::test
