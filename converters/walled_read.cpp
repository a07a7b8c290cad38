#include "converters/walled_read.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>

#include "core/number_format.hpp"
#include "formats/common/file_io.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/scene_stream/scene_stream.hpp"
#include "formats/step/step_reader.hpp"

namespace cadnurbs {

namespace {

constexpr int kStreamFd = 3;  // the child's translation stream
constexpr int kStageFd = 4;   // the child's stage lines

BrepTranslation read_in_process(const std::string& path, const std::string& format, const ReadStageListener& stage) {
  return format == "IGES" ? read_iges(path, stage) : read_step(path, stage);
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

// In the forked child: the pipes on fds 3 and 4 (limited_child puts the standard streams on /dev/null:
// OCCT prints, and the parent speaks for the child).
void keep_pipes(int stream_fd, int stage_fd) {
  // Fds 3 and 4 may be the pipes themselves: move them out of the way first.
  const int stream = ::fcntl(stream_fd, F_DUPFD, 10), stage = ::fcntl(stage_fd, F_DUPFD, 10);
  if (stream < 0 || stage < 0 || ::dup2(stream, kStreamFd) < 0 || ::dup2(stage, kStageFd) < 0) _exit(126);
}

// The child's outcome as the one-line error, or empty when it read the file.
std::string outcome(const std::string& path, int status, bool timed_out, const ChildReport& report,
                    const ProcessLimits& limits) {
  const std::string stage = stage_words(report.stage);
  const std::string megabytes = std::to_string(limits.megabytes);
  if (timed_out) return path + ": " + limited_child_end(status, true, limits) + " while " + stage;
  if (report.out_of_memory) return path + ": exceeded the memory limit of " + megabytes + " MB while " + stage;
  if (const std::string end = limited_child_end(status, false, limits); !end.empty())
    return path + ": " + end + " while " + stage;
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
// stage lines to fd 4 (calling `hook` as each stage starts), and ends the process (0 read, 1 refused).
[[noreturn]] void serve_read(const std::string& format, const std::string& path, const ReadStageListener& hook) {
  std::set_new_handler([] {
    write_all(kStageFd, "memory\n");
    _exit(3);
  });
  const ReadStageListener tell_parent = [&](const std::string& stage) {
    write_all(kStageFd, "stage " + stage + "\n");
    tell_stage(hook, stage);
  };
  try {
    write_all(kStreamFd, write_translation_stream(read_in_process(path, format, tell_parent)));
  } catch (const std::exception& error) {
    std::string line = error.what();
    for (char& c : line) if (c == '\n') c = ' ';
    write_all(kStageFd, "error " + line + "\n");
    _exit(1);
  }
  _exit(0);  // no OCCT static destructors: nothing of them is needed, and they are not always quick
}

BrepTranslation read_walled(const std::string& path, const std::string& format, const BrepReadOptions& options) {
  const ProcessLimits& limits = options.limits;
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
  const bool read_in_fork = single_threaded() && !options.always_exec;
  std::string name = "cadnurbs", subcommand = "__read-brep", format_arg = format, path_arg = path;
  char* argv[] = {name.data(), subcommand.data(), format_arg.data(), path_arg.data(), nullptr};
  const pid_t child = fork_limited_child(
      limits, [&] { keep_pipes(stream_pipe[1], stage_pipe[1]); },
      [&]() -> int {
        if (read_in_fork) serve_read(format, path, options.child_stage_hook);
        ::execv("/proc/self/exe", argv);
        return 127;
      });
  ::close(stream_pipe[1]);
  ::close(stage_pipe[1]);
  if (child < 0) {
    ::close(stream_pipe[0]);
    ::close(stage_pipe[0]);
    throw FileError(path + ": cannot start the reading process (" + std::strerror(errno) + ")");
  }

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

BrepTranslation read_brep(const std::string& path, const std::string& format, const BrepReadOptions& options) {
  return options.walled ? read_walled(path, format, options) : read_in_process(path, format, {});
}

int run_read_brep_child(const std::vector<std::string>& args, const ReadStageListener& hook) {
  if (args.size() != 2) return 2;
  serve_read(args[0], args[1], hook);
}

}  // namespace cadnurbs
