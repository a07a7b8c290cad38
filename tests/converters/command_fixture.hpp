#pragma once
// The cadnurbs command run as a user runs it, each test in a fresh folder of its own (removed afterwards):
// the fixture of the command-line tests.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "formats/common/file_io.hpp"

namespace cadnurbs::test {

struct CommandResult {
  int status;
  std::string out, err;
};

class CommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("cadnurbs_" + std::string(info->test_suite_name()) + "_" + std::to_string(::getpid()) + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // `cadnurbs ARGUMENTS` with stdout and stderr kept in the folder (stdout.txt, stderr.txt).
  CommandResult run(const std::string& arguments, const std::string& environment = "") {
    return run_program(CADNURBS_EXE, arguments, environment);
  }
  // The same with another executable that runs the cadnurbs command line.
  CommandResult run_program(const std::string& program, const std::string& arguments,
                            const std::string& environment = "") {
    const std::string out = path("stdout.txt"), err = path("stderr.txt");
    const int status = std::system((environment + program + " " + arguments + " >" + out + " 2>" + err).c_str());
    return {WEXITSTATUS(status), read_file(out), read_file(err)};
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

}  // namespace cadnurbs::test
