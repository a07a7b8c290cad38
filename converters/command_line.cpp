#include "converters/command_line.hpp"

#include <algorithm>
#include <iostream>

#include "converters/commands.hpp"

namespace cadnurbs {

namespace {

// Every command's synopsis, made from its table of options as its own --help is.
std::string usage() {
  std::string text = "usage: cadnurbs COMMAND [options]\ncommands:\n";
  for (const Command& command : commands()) {
    const std::string synopsis = command_synopsis(command.spec());
    for (size_t start = 0; start <= synopsis.size();) {
      const size_t end = std::min(synopsis.find('\n', start), synopsis.size());
      text += "  " + synopsis.substr(start, end - start) + "\n";
      start = end + 1;
    }
  }
  return text + "'cadnurbs COMMAND --help' tells more.\n";
}

}  // namespace

SceneReadOptions scene_read_options(const Arguments& a, const CommandContext& context) {
  SceneReadOptions options;
  options.homogeneous_control_points = !a.has("euclidean");
  options.brep.walled = context.read_wall;
  options.brep.limits = read_limits(a);
  options.brep.step_reader = step_reader_choice(a);
  options.brep.child_stage_hook = context.child_stage_hook;
  options.brep.always_exec = context.always_exec;
  return options;
}

int run_command_line(int argc, char** argv, CommandContext context) {
  if (argc < 2) {
    std::cerr << usage();
    return 2;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    std::cout << usage();
    return 0;
  }
  if (name == "__read-brep") return run_read_brep_child({argv + 2, argv + argc}, context.child_stage_hook);
  context.read_wall = true;
  const Command* command = find_command(name);
  if (!command) {
    std::cerr << "cadnurbs: unknown command '" << name << "'\n" << usage();
    return 2;
  }
  try {
    return command->run({argv + 2, argv + argc}, context);
  } catch (const UsageError& e) {
    std::cerr << "cadnurbs " << name << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "cadnurbs " << name << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace cadnurbs
