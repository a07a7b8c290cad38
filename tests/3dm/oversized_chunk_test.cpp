// A chunk length larger than the file must be refused before anything is allocated for it: the reader runs
// in a forked child whose address space is capped at what it already uses plus 256 MiB, on a corpus file
// with one chunk length patched to 2^40 (8-byte lengths, archive version 70) or to 2^31 - 1 (4-byte
// lengths, version 2: enough to tempt a reader into a 2 GiB buffer). It must come back with an ArchiveError
// naming the patched chunk's typecode and offset, not run out of memory or crash. (The fuzz test
// 3dm.fuzz bounds memory the same way for mutated inputs, with -rss_limit_mb=512 -malloc_limit_mb=512.)
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>
#include <string>

#include "formats/3dm/rhino_file.hpp"
#include "formats/3dm/typecodes.hpp"
#include "formats/common/file_io.hpp"

namespace {

using namespace cadnurbs::rhino;

std::string corpus(const char* name) { return cadnurbs::read_file(std::string(CADNURBS_SHARED_DIR "/corpus/3dm/") + name); }

int archive_version(const std::string& bytes) { return std::stoi(bytes.substr(24, 8)); }

// The header of the first chunk with `typecode`, searched among the top-level chunks and, with
// `inside`, among the chunks of the first top-level chunk with typecode `inside`.
ChunkHeader find_chunk(const std::string& bytes, std::uint32_t typecode, std::uint32_t inside = 0) {
  ArchiveReader reader(bytes, "find", archive_version(bytes), 32);
  while (reader.bytes_left() > 0) {
    const ChunkHeader header = reader.begin_chunk();
    if (header.is_short()) continue;
    if (inside == 0 && header.typecode == typecode) return header;
    if (inside != 0 && header.typecode == inside) {
      while (reader.bytes_left() > 0) {
        const ChunkHeader nested = reader.begin_chunk();
        if (nested.typecode == typecode) return nested;
        if (!nested.is_short()) reader.end_chunk();
      }
    }
    reader.end_chunk();
  }
  throw std::runtime_error("chunk not found");
}

// The length field of `header` set to `length` (8 or 4 bytes after the typecode).
std::string patched(std::string bytes, const ChunkHeader& header, std::int64_t length) {
  if (archive_version(bytes) >= 50) {
    std::memcpy(bytes.data() + header.offset + 4, &length, 8);
  } else {
    const auto length32 = static_cast<std::int32_t>(length);
    std::memcpy(bytes.data() + header.offset + 4, &length32, 4);
  }
  return bytes;
}

std::size_t address_space_in_use() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

struct ChildOutcome {
  int exit_code = -1;  // 0 ArchiveError, 1 parsed, 2 bad_alloc, 3 other exception; -1 killed by a signal
  std::string message;
};

// parse_3dm in a child process whose address space may grow by 256 MiB at most.
ChildOutcome parse_with_capped_memory(const std::string& bytes) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw std::runtime_error("pipe");
  const pid_t pid = fork();
  if (pid == 0) {
    close(pipe_fds[0]);
    const rlim_t cap = address_space_in_use() + (rlim_t{256} << 20);
    const rlimit limit{cap, cap};
    setrlimit(RLIMIT_AS, &limit);
    int code = 3;
    std::string message;
    try {
      (void)parse_3dm(bytes, "patched.3dm");
      code = 1;
    } catch (const ArchiveError& e) {
      code = 0;
      message = e.what();
    } catch (const std::bad_alloc&) {
      code = 2;
    } catch (const std::exception& e) {
      message = e.what();
    }
    if (!message.empty()) (void)!write(pipe_fds[1], message.data(), message.size());
    _exit(code);
  }
  close(pipe_fds[1]);
  ChildOutcome outcome;
  char buffer[512];
  for (ssize_t n; (n = read(pipe_fds[0], buffer, sizeof buffer)) > 0;) outcome.message.append(buffer, n);
  close(pipe_fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
  return outcome;
}

std::string chunk_words(const ChunkHeader& header) {
  char text[64];
  std::snprintf(text, sizeof text, "chunk 0x%08X at offset %zu", header.typecode, header.offset);
  return text;
}

void expect_refused(const std::string& original, const ChunkHeader& header, std::int64_t length) {
  ASSERT_GT(static_cast<std::uint64_t>(length), original.size());
  const ChildOutcome outcome = parse_with_capped_memory(patched(original, header, length));
  ASSERT_EQ(outcome.exit_code, 0) << "0 ArchiveError, 1 parsed, 2 out of memory, 3 other exception, -1 signal; "
                                  << outcome.message;
  EXPECT_NE(outcome.message.find(chunk_words(header)), std::string::npos) << outcome.message;
  EXPECT_EQ(outcome.message.find('\n'), std::string::npos) << outcome.message;
}

TEST(OversizedChunk, ObjectTableLengthTwoToTheFortyRefusedWithinCappedMemory) {
  const std::string bytes = corpus("v7_my_brep.3dm");
  ASSERT_EQ(archive_version(bytes), 70);
  expect_refused(bytes, find_chunk(bytes, tcode::kObjectTable), std::int64_t{1} << 40);
}

TEST(OversizedChunk, ObjectRecordLengthTwoToTheFortyRefusedWithinCappedMemory) {
  const std::string bytes = corpus("v7_my_brep.3dm");
  expect_refused(bytes, find_chunk(bytes, tcode::kObjectRecord, tcode::kObjectTable), std::int64_t{1} << 40);
}

TEST(OversizedChunk, FourByteLengthOfTwoGigabytesRefusedWithinCappedMemory) {
  const std::string bytes = corpus("v2_my_trimmed_surface.3dm");
  ASSERT_EQ(archive_version(bytes), 2);
  expect_refused(bytes, find_chunk(bytes, tcode::kObjectRecord, tcode::kObjectTable), 0x7FFFFFFF);
}

// The unpatched files parse in the same capped child, so the cap itself does not cause the refusals.
TEST(OversizedChunk, UnpatchedFilesParseWithinCappedMemory) {
  for (const char* name : {"v7_my_brep.3dm", "v2_my_trimmed_surface.3dm"})
    EXPECT_EQ(parse_with_capped_memory(corpus(name)).exit_code, 1) << name;
}

}  // namespace
