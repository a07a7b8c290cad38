#pragma once
// STEP/IGES reads behind a wall: OCCT runs in a child process under CPU-time, wall-time and address-space
// limits, and hands the result back as a translation stream (formats/scene_stream). The child is a plain
// fork when the process runs one thread (as convert and info do when they read), else this executable
// again with the hidden subcommand `__read-brep FORMAT PATH` (fork and exec). A crash, a hang or a limit in OCCT then costs
// the child, not the command, and becomes one line naming the file, the stage and the reason.
#include <string>
#include <vector>

#include "formats/brep/brep_translation.hpp"

namespace cadnurbs {

struct ReadLimits {
  double seconds = 120;      // wall time, and CPU time, of one read (--time-limit)
  long megabytes = 4096;     // address space of the reading process (--memory-limit)
};

// The limits of the next reads, process-wide: convert, info and report set them from their options.
ReadLimits& read_limits();

// Only an executable that serves `__read-brep` (the cadnurbs main) turns the wall on; without it (tests
// and tools linking the converters library) STEP and IGES are read in-process. bench/ turns it off again
// to compare.
void enable_read_wall(bool on = true);
bool read_wall_enabled();

// read_step (format "STEP") or read_iges ("IGES") of `path`: behind the wall when it is enabled, else
// in-process. Behind the wall, refuses (FileError, one line) with the child's own error unchanged, or
// "<path>: crashed with SIGSEGV while parsing" (any signal; stages: "starting", "parsing",
// "transferring", "converting face N"), "<path>: exceeded 120 s while transferring" (wall or CPU time),
// "<path>: exceeded the memory limit of 4096 MB while parsing", "<path>: the reading process failed
// while ... (exit status N)".
BrepTranslation read_brep(const std::string& path, const std::string& format);

// The child's side, `cadnurbs __read-brep FORMAT PATH`: reads, writes the translation stream to fd 3 and
// stage lines ("stage parse", ..., "error MESSAGE", "memory") to fd 4. Exit status 0 when read, 1 when
// refused. A test hook: CADNURBS_WALL_FAULT=STAGE:segv|xcpu|sleep|alloc makes the child crash, receive
// the kernel's CPU-limit signal, sleep for ever or allocate without end when STAGE ("parse", "transfer",
// "face 1", ...) starts; CADNURBS_WALL_EXEC=1 makes a single-threaded process exec its child too.
int run_read_brep_child(const std::vector<std::string>& args);

}  // namespace cadnurbs
