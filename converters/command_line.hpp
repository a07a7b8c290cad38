#pragma once
// The `cadnurbs` command line as a library function, so that the executable's main is one line and tests
// can run the same dispatch with their own context: it picks the command, serves the hidden child side of
// the STEP/IGES wall (`__read-brep`), and turns errors into one line (exit 2 for usage, 1 for the rest).
#include <string>

#include "converters/arguments.hpp"
#include "converters/file_formats.hpp"

namespace cadnurbs {

// What the executable that runs the commands can do, passed to every command.
struct CommandContext {
  // The executable serves `__read-brep` (run_command_line does), so STEP/IGES reads may go through the
  // wall; commands run by other code (tests calling run_convert) read in-process.
  bool read_wall = false;
  // For tests of the wall only (BrepReadOptions says what they do).
  ReadStageListener child_stage_hook;
  bool always_exec = false;
};

// The reading options of a command that reads CAD files: --euclidean (when the command has it), the wall
// of `context` with the limits of --time-limit and --memory-limit (read_limits).
SceneReadOptions scene_read_options(const Arguments& a, const CommandContext& context);

// `cadnurbs ARGS...` with argv as main gets it; the context's read_wall is set, since this serves the
// wall's child side.
int run_command_line(int argc, char** argv, CommandContext context = {});

}  // namespace cadnurbs
