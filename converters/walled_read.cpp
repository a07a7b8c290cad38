#include "converters/walled_read.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <thread>

#include "converters/process_limits.hpp"
#include "formats/brep/read_stage.hpp"
#include "formats/common/file_io.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/scene_stream/scene_stream.hpp"
#include "formats/step/step_reader.hpp"

namespace cadnurbs {

namespace {

constexpr int kStreamFd = 3;  // the child's translation stream
constexpr int kStageFd = 4;   // the child's stage lines

bool& wall_enabled() {
  static bool enabled = false;
  return enabled;
}

BrepTranslation read_in_process(const std::string& path, const std::string& format) {
  return format == "IGES" ? read_iges(path) : read_step(path);
}

// All of `text` to `fd`, whatever the pipe takes at a time.
void write_all(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(2);  // the parent is gone: nobody to tell
    text.remove_prefix(static_cast<size_t>(n));
  }
}

// "stage X" lines as words for messages: "parse" -> "parsing", "face 3" -> "converting face 3".
std::string stage_words(const std::string& stage) {
  if (stage.empty()) return "starting";
  if (stage == "parse") return "parsing";
  if (stage == "transfer") return "transferring";
  return "converting " + stage;
}

std::string signal_name(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
}

std::string number_text(double x) {
  const std::string text = std::to_string(x);
  if (x == std::floor(x)) return std::to_string(static_cast<long long>(x));
  return text.substr(0, text.find_last_not_of('0') + 1);
}

// What the child said on its stage fd.
struct ChildReport {
  std::string stage;  // the last stage started
  std::string error;  // its one-line refusal
  bool out_of_memory = false;
};

void take_lines(std::string& pending, ChildReport& report) {
  for (size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1)) {
    const std::string line = pending.substr(0, end);
    if (line.rfind("stage ", 0) == 0) report.stage = line.substr(6);
    else if (line.rfind("error ", 0) == 0) report.error = line.substr(6);
    else if (line == "memory") report.out_of_memory = true;
  }
}

// True when this process runs one thread. Only then may a fork run OCCT without exec: no lock another
// thread held at the fork stays locked in the child, and no thread pool's workers go missing there.
bool single_threaded() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Threads:", 0) == 0) return std::atoi(line.c_str() + 8) == 1;
  return false;
}

// In the forked child: its own process group, the pipes on fds 3 and 4, stdin/stdout/stderr on
// /dev/null (OCCT prints; the parent speaks for the child), the CPU, address-space and core limits.
void prepare_child(int stream_fd, int stage_fd, const ReadLimits& limits) {
  ::setpgid(0, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // its own process group: a killed parent's group kill misses it
  // Fds 3 and 4 may be the pipes themselves: move them out of the way first.
  const int stream = ::fcntl(stream_fd, F_DUPFD, 10), stage = ::fcntl(stage_fd, F_DUPFD, 10);
  if (stream < 0 || stage < 0 || ::dup2(stream, kStreamFd) < 0 || ::dup2(stage, kStageFd) < 0) _exit(126);
  const int null = ::open("/dev/null", O_RDWR);
  if (null < 0 || ::dup2(null, 0) < 0 || ::dup2(null, 1) < 0 || ::dup2(null, 2) < 0) _exit(126);
  limit_this_process(limits.seconds, limits.megabytes);
}

// The child's outcome as the one-line error, or empty when it read the file.
std::string outcome(const std::string& path, int status, bool timed_out, const ChildReport& report,
                    const ReadLimits& limits) {
  const std::string stage = stage_words(report.stage);
  const std::string megabytes = std::to_string(limits.megabytes);
  if (timed_out) return path + ": exceeded " + number_text(limits.seconds) + " s while " + stage;
  if (report.out_of_memory) return path + ": exceeded the memory limit of " + megabytes + " MB while " + stage;
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    if (signal == SIGXCPU || signal == SIGKILL)  // SIGKILL from the kernel: the hard CPU limit
      return path + ": exceeded " + number_text(limits.seconds) + " s of CPU time while " + stage;
    return path + ": crashed with " + signal_name(signal) + " while " + stage;
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 0 && report.error.empty()) return "";
  if (!report.error.empty()) {
    // OCCT's allocator reports a failed allocation as an exception the reader turns into its message.
    if (report.error.find("OutOfMemory") != std::string::npos || report.error.find("bad_alloc") != std::string::npos)
      return path + ": exceeded the memory limit of " + megabytes + " MB while " + stage;
    return report.error;
  }
  return path + ": the reading process failed while " + stage + " (exit status " + std::to_string(code) + ")";
}

// The child's work, in a fork or after exec: reads `path`, writes the translation stream to fd 3 and the
// stage lines to fd 4, and ends the process (0 read, 1 refused).
[[noreturn]] void serve_read(const std::string& format, const std::string& path) {
  std::string fault_stage, fault_action;
  if (const char* fault = std::getenv("CADNURBS_WALL_FAULT")) {
    const std::string text = fault;
    fault_stage = text.substr(0, text.find(':'));
    fault_action = text.find(':') == std::string::npos ? "" : text.substr(text.find(':') + 1);
  }
  std::set_new_handler([] {
    write_all(kStageFd, "memory\n");
    _exit(3);
  });
  set_read_stage_listener([&](const std::string& stage) {
    write_all(kStageFd, "stage " + stage + "\n");
    if (stage != fault_stage) return;
    if (fault_action == "segv" || fault_action == "xcpu") {
      const int signal = fault_action == "segv" ? SIGSEGV : SIGXCPU;
      ::signal(signal, SIG_DFL);  // OCCT's handler would turn it into an exception
      ::raise(signal);
    } else if (fault_action == "sleep") {
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
    } else if (fault_action == "alloc") {
      // Address space, not pages: untouched blocks reach the limit without using the machine's memory.
      for (std::vector<std::unique_ptr<char[]>> hog;;) hog.emplace_back(new char[1 << 20]);
    }
  });
  try {
    write_all(kStreamFd, write_translation_stream(read_in_process(path, format)));
  } catch (const std::exception& error) {
    std::string line = error.what();
    for (char& c : line) if (c == '\n') c = ' ';
    write_all(kStageFd, "error " + line + "\n");
    _exit(1);
  }
  _exit(0);  // no OCCT static destructors: nothing of them is needed, and they are not always quick
}

BrepTranslation read_walled(const std::string& path, const std::string& format) {
  const ReadLimits limits = read_limits();
  int stream_pipe[2], stage_pipe[2];
  if (::pipe2(stream_pipe, O_CLOEXEC) != 0) throw FileError(path + ": cannot start the reading process (" + std::strerror(errno) + ")");
  if (::pipe2(stage_pipe, O_CLOEXEC) != 0) {
    ::close(stream_pipe[0]);
    ::close(stream_pipe[1]);
    throw FileError(path + ": cannot start the reading process (" + std::strerror(errno) + ")");
  }
  // A single-threaded process forks and reads in the copy: it has this executable and OCCT loaded already
  // (starting them again costs 0.1-0.5 s, more than most reads). Otherwise the child execs itself
  // (`__read-brep`) and may only make async-signal-safe calls until then; argv is made before the fork.
  const bool read_in_fork = single_threaded() && !std::getenv("CADNURBS_WALL_EXEC");  // the variable: for tests
  std::string name = "cadnurbs", subcommand = "__read-brep", format_arg = format, path_arg = path;
  char* argv[] = {name.data(), subcommand.data(), format_arg.data(), path_arg.data(), nullptr};
  std::cout.flush();  // what the parent has buffered must not be written again by the child
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    prepare_child(stream_pipe[1], stage_pipe[1], limits);
    if (read_in_fork) serve_read(format, path);
    ::execv("/proc/self/exe", argv);
    _exit(127);
  }
  ::close(stream_pipe[1]);
  ::close(stage_pipe[1]);
  if (child < 0) {
    ::close(stream_pipe[0]);
    ::close(stage_pipe[0]);
    throw FileError(path + ": cannot start the reading process (" + std::strerror(errno) + ")");
  }
  ::setpgid(child, child);  // also here: kill(-child) must work even before the child runs

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
  std::string stream, pending;
  ChildReport report;
  pollfd fds[2] = {{stream_pipe[0], POLLIN, 0}, {stage_pipe[0], POLLIN, 0}};
  bool timed_out = false;
  char buffer[1 << 16];
  while (fds[0].fd >= 0 || fds[1].fd >= 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    const int ready = ::poll(fds, 2, static_cast<int>(std::min<long long>(left.count() + 1, 1 << 30)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) break;
    for (int k = 0; k < 2; ++k) {
      if (fds[k].fd < 0 || fds[k].revents == 0) continue;
      const ssize_t n = ::read(fds[k].fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        ::close(fds[k].fd);
        fds[k].fd = -1;
        continue;
      }
      if (k == 0) {
        stream.append(buffer, static_cast<size_t>(n));
      } else {
        pending.append(buffer, static_cast<size_t>(n));
        take_lines(pending, report);
      }
    }
  }
  for (auto& fd : fds) if (fd.fd >= 0) ::close(fd.fd);
  if (timed_out) ::kill(-child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (const std::string error = outcome(path, status, timed_out, report, limits); !error.empty()) throw FileError(error);
  return read_translation_stream(stream, path + " (from the reading process)");
}

}  // namespace

ReadLimits& read_limits() {
  static ReadLimits limits;
  return limits;
}

void enable_read_wall(bool on) { wall_enabled() = on; }
bool read_wall_enabled() { return wall_enabled(); }

BrepTranslation read_brep(const std::string& path, const std::string& format) {
  return wall_enabled() ? read_walled(path, format) : read_in_process(path, format);
}

int run_read_brep_child(const std::vector<std::string>& args) {
  if (args.size() != 2) return 2;
  serve_read(args[0], args[1]);
}

}  // namespace cadnurbs
