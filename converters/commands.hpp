#pragma once
// The cadnurbs subcommands. Each takes its arguments (after the subcommand name) and what the executable
// can do (CommandContext), prints to stdout, and returns the exit status; errors propagate as exceptions
// that run_command_line turns into one line.
// Each also describes itself (CommandSpec: forms, text, options), the one table its parser, its --help
// and `cadnurbs --help` read.
#include <string>
#include <vector>

#include "converters/arguments.hpp"
#include "converters/command_line.hpp"

namespace cadnurbs {

int run_convert(const std::vector<std::string>& args, const CommandContext& context = {});
int run_info(const std::vector<std::string>& args, const CommandContext& context = {});
int run_capping(const std::vector<std::string>& args, const CommandContext& context = {});
int run_demo(const std::vector<std::string>& args, const CommandContext& context = {});
int run_report(const std::vector<std::string>& args, const CommandContext& context = {});
int run_normals(const std::vector<std::string>& args, const CommandContext& context = {});
int run_fit_loop(const std::vector<std::string>& args, const CommandContext& context = {});
int run_batch(const std::vector<std::string>& args, const CommandContext& context = {});
int run_fit_path(const std::vector<std::string>& args, const CommandContext& context = {});

const CommandSpec& convert_command_spec();
const CommandSpec& info_command_spec();
const CommandSpec& capping_command_spec();
const CommandSpec& demo_command_spec();
const CommandSpec& report_command_spec();
const CommandSpec& normals_command_spec();
const CommandSpec& fit_loop_command_spec();
const CommandSpec& batch_command_spec();
const CommandSpec& fit_path_command_spec();

struct Command {
  int (*run)(const std::vector<std::string>& args, const CommandContext& context);
  const CommandSpec& (*spec)();  // its name is spec().name
};

// Every command, in the order `cadnurbs --help` lists them: main runs them from it, the help test checks
// each.
inline const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {run_convert, convert_command_spec},
      {run_info, info_command_spec},
      {run_capping, capping_command_spec},
      {run_report, report_command_spec},
      {run_normals, normals_command_spec},
      {run_fit_loop, fit_loop_command_spec},
      {run_fit_path, fit_path_command_spec},
      {run_batch, batch_command_spec},
      {run_demo, demo_command_spec},
  };
  return table;
}

// The command called `name`, or nullptr.
inline const Command* find_command(const std::string& name) {
  for (const Command& command : commands())
    if (command.spec().name == name) return &command;
  return nullptr;
}

}  // namespace cadnurbs
