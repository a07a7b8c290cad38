#include "converters/limited_child.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "core/number_format.hpp"

namespace cadnurbs {

namespace {

// CPU time `seconds` (rounded up; SIGXCPU then, SIGKILL a second later), address space `megabytes`, no
// core files.
void limit_this_process(const ProcessLimits& limits) {
  const rlim_t cpu = static_cast<rlim_t>(std::ceil(limits.seconds));
  const rlimit cpu_limit{cpu, cpu + 1};
  const rlim_t bytes = static_cast<rlim_t>(limits.megabytes) << 20;
  const rlimit memory_limit{bytes, bytes}, no_core{0, 0};
  ::setrlimit(RLIMIT_CPU, &cpu_limit);
  ::setrlimit(RLIMIT_AS, &memory_limit);
  ::setrlimit(RLIMIT_CORE, &no_core);
}

}  // namespace

pid_t fork_limited_child(const ProcessLimits& limits, const std::function<void()>& keep_fds,
                         const std::function<int()>& body) {
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t parent = ::getpid();
  const pid_t child = ::fork();
  if (child == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // its own process group: a killed parent's group kill misses it
    if (::getppid() != parent) _exit(1);  // the parent died before the line above
    if (keep_fds) keep_fds();
    const int null = ::open("/dev/null", O_RDWR);
    if (null < 0 || ::dup2(null, 0) < 0 || ::dup2(null, 1) < 0 || ::dup2(null, 2) < 0) _exit(126);
    limit_this_process(limits);
    int status = 1;
    try {
      status = body();
    } catch (...) {
      status = 1;
    }
    _exit(status);  // no static destructors of the parent's copy: nothing of them is needed here
  }
  if (child > 0) ::setpgid(child, child);  // also here: kill(-child) must work even before the child runs
  return child;
}

std::string signal_name(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
}

std::string limited_child_end(int status, bool timed_out, const ProcessLimits& limits) {
  if (timed_out) return "exceeded " + number_text(limits.seconds, 6) + " s";
  if (!WIFSIGNALED(status)) return "";
  const int signal = WTERMSIG(status);
  if (signal == SIGXCPU || signal == SIGKILL)  // SIGKILL from the kernel: the hard CPU limit
    return "exceeded " + number_text(limits.seconds, 6) + " s of CPU time";
  return "crashed with " + signal_name(signal);
}

}  // namespace cadnurbs
