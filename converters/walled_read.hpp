#pragma once
// STEP/IGES reads behind a wall: OCCT runs in a child process (converters/limited_child) under CPU-time,
// wall-time and address-space limits, and hands the result back as a translation stream
// (formats/scene_stream). The child is a plain fork when the process runs one thread (as convert and info
// do when they read), else this executable again with the hidden subcommand `__read-brep FORMAT PATH`
// (fork and exec). A crash, a hang or a limit in OCCT then costs the child, not the command, and becomes
// one line naming the file, the stage and the reason.
#include <string>
#include <vector>

#include "converters/limited_child.hpp"
#include "formats/brep/brep_translation.hpp"
#include "formats/brep/read_stage.hpp"

namespace cadnurbs {

// How a STEP or IGES file is read.
// Which reader reads STEP: ours, falling back to OpenCASCADE's for a file outside its subset (said in
// BrepTranslation::notes); ours only; OpenCASCADE's only.
enum class StepReaderChoice { native_then_occt, native, occt };

struct BrepReadOptions {
  StepReaderChoice step_reader = StepReaderChoice::native_then_occt;
  // Behind the wall. Only an executable that serves `__read-brep` (cadnurbs; tests' own copies of its
  // main) may ask for it; without it STEP and IGES are read in this process.
  bool walled = false;
  ProcessLimits limits;  // of the reading child: --time-limit and --memory-limit, 120 s and 4096 MB by default
  // For tests of the wall: called in the reading child as each stage starts (before the reader goes on), so
  // that a test can make the child crash, hang or allocate there; and the child execs itself even from a
  // single-threaded process, as a process with threads must. An executable that sets the hook must pass
  // the same hook to run_read_brep_child for its `__read-brep`.
  ReadStageListener child_stage_hook;
  bool always_exec = false;
};

// read_step (format "STEP") or read_iges ("IGES") of `path`: behind the wall when `options.walled`, else
// in-process. Behind the wall, refuses (FileError, one line) with the child's own error unchanged, or
// "<path>: crashed with SIGSEGV while parsing" (any signal; stages: "starting", "parsing",
// "transferring", "converting face N"), "<path>: exceeded 120 s while transferring" (wall or CPU time),
// "<path>: exceeded the memory limit of 4096 MB while parsing", "<path>: the reading process failed
// while ... (exit status N)".
BrepTranslation read_brep(const std::string& path, const std::string& format, const BrepReadOptions& options);

// The child's side after exec, `cadnurbs __read-brep FORMAT PATH`: reads, writes the translation stream to
// fd 3 and stage lines ("stage parse", ..., "error MESSAGE", "memory") to fd 4; `hook` as child_stage_hook
// above. Exit status 0 when read, 1 when refused, 2 for wrong arguments.
int run_read_brep_child(const std::vector<std::string>& args, const ReadStageListener& hook = {});

}  // namespace cadnurbs
