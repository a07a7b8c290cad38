#include "converters/batch/worker_pool.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <thread>

#include "converters/process_limits.hpp"

namespace cadnurbs {

namespace {

using Clock = std::chrono::steady_clock;

std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

[[noreturn]] void become_worker(pid_t batch, const WorkerLimits& limits, const std::function<int(int)>& task, int i) {
  ::setpgid(0, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // a killed batch leaves no worker behind
  if (::getppid() != batch) _exit(1);  // the batch died before the line above
  const int null = ::open("/dev/null", O_RDWR);
  if (null < 0 || ::dup2(null, 0) < 0 || ::dup2(null, 1) < 0 || ::dup2(null, 2) < 0) _exit(126);
  limit_this_process(limits.seconds, limits.megabytes);
  int status = 1;
  try {
    status = task(i);
  } catch (...) {
    status = 1;
  }
  _exit(status);  // no static destructors of the parent's copy
}

}  // namespace

std::string WorkerOutcome::reason(const WorkerLimits& limits) const {
  if (!not_started.empty()) return "no worker could be started (fork: " + not_started + ")";
  if (timed_out) return "exceeded " + number_text(limits.seconds) + " s";
  if (signal == SIGXCPU || signal == SIGKILL) return "exceeded " + number_text(limits.seconds) + " s of CPU time";
  if (signal != 0) {
    const char* name = sigabbrev_np(signal);
    return std::string("crashed with ") + (name ? std::string("SIG") + name : "signal " + std::to_string(signal));
  }
  if (exit_status == 0) return "";
  return "the worker ended with exit status " + std::to_string(exit_status);
}

void run_in_workers(int count, int jobs, const WorkerLimits& limits, const std::function<int(int)>& task,
                    const std::function<void(int, const WorkerOutcome&)>& done) {
  struct Running {
    int task;
    Clock::time_point start;
    bool killed = false;
  };
  std::map<pid_t, Running> running;
  int next = 0;
  while (next < count || !running.empty()) {
    while (next < count && static_cast<int>(running.size()) < std::max(1, jobs)) {
      std::cout.flush();
      std::cerr.flush();
      std::fflush(nullptr);
      const pid_t batch = ::getpid();
      const pid_t pid = ::fork();
      if (pid == 0) become_worker(batch, limits, task, next);
      if (pid < 0) {
        WorkerOutcome failed;
        failed.not_started = std::strerror(errno);
        done(next++, failed);
        continue;
      }
      ::setpgid(pid, pid);
      running[pid] = {next++, Clock::now()};
    }
    int status = 0;
    const pid_t ended = ::waitpid(-1, &status, WNOHANG);
    if (ended > 0 && running.count(ended)) {
      const Running r = running[ended];
      running.erase(ended);
      ::kill(-ended, SIGKILL);  // whatever the worker started (the STEP/IGES wall's child) goes with it
      WorkerOutcome outcome;
      outcome.seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
      outcome.timed_out = r.killed;
      if (WIFEXITED(status)) outcome.exit_status = WEXITSTATUS(status);
      if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
      done(r.task, outcome);
      continue;
    }
    const auto now = Clock::now();
    for (auto& [pid, r] : running)
      if (!r.killed && std::chrono::duration<double>(now - r.start).count() > limits.seconds) {
        ::kill(-pid, SIGKILL);
        r.killed = true;
      }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace cadnurbs
