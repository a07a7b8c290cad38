#pragma once
// The cadnurbs subcommands. Each takes its arguments (after the subcommand name), prints to
// stdout, and returns the exit status; errors propagate as exceptions that main turns into one line.
#include <string>
#include <vector>

namespace cadnurbs {

int run_convert(const std::vector<std::string>& args);
int run_info(const std::vector<std::string>& args);
int run_capping(const std::vector<std::string>& args);
int run_demo(const std::vector<std::string>& args);
int run_report(const std::vector<std::string>& args);
int run_normals(const std::vector<std::string>& args);
int run_fit_loop(const std::vector<std::string>& args);
int run_batch(const std::vector<std::string>& args);
int run_fit_path(const std::vector<std::string>& args);

}  // namespace cadnurbs
