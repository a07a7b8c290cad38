// cadnurbs with faults in its STEP/IGES wall, for walled_read_test: the same command line
// (converters/command_line.hpp) whose reading child, when CADNURBS_TEST_FAULT=STAGE:ACTION is set,
// crashes (segv), receives the kernel's CPU-limit signal (xcpu), sleeps for ever (sleep) or allocates
// without end (alloc) as STAGE ("parse", "transfer", "face 1", ...) starts; CADNURBS_TEST_EXEC=1 makes
// a single-threaded process exec its reading child too, as a process with threads must. The faults live
// here, in a test executable, so that cadnurbs itself has none.
#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "converters/command_line.hpp"

namespace {

void act(const std::string& action) {
  if (action == "segv" || action == "xcpu") {
    const int signal = action == "segv" ? SIGSEGV : SIGXCPU;
    ::signal(signal, SIG_DFL);  // OCCT's handler would turn it into an exception
    ::raise(signal);
  } else if (action == "sleep") {
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
  } else if (action == "alloc") {
    // Address space, not pages: untouched blocks reach the limit without using the machine's memory.
    for (std::vector<std::unique_ptr<char[]>> hog;;) hog.emplace_back(new char[1 << 20]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  cadnurbs::CommandContext context;
  if (const char* fault = std::getenv("CADNURBS_TEST_FAULT")) {
    const std::string text = fault;
    const std::string stage = text.substr(0, text.find(':'));
    const std::string action = text.find(':') == std::string::npos ? "" : text.substr(text.find(':') + 1);
    context.child_stage_hook = [stage, action](const std::string& started) {
      if (started == stage) act(action);
    };
  }
  context.always_exec = std::getenv("CADNURBS_TEST_EXEC") != nullptr;
  return cadnurbs::run_command_line(argc, argv, context);
}
