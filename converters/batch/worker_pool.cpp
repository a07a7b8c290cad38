#include "converters/batch/worker_pool.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <thread>

namespace cadnurbs {

namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

std::string WorkerOutcome::reason(const ProcessLimits& limits) const {
  if (!not_started.empty()) return "no worker could be started (fork: " + not_started + ")";
  if (const std::string end = limited_child_end(status, timed_out, limits); !end.empty()) return end;
  const int exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (exit_status == 0) return "";
  return "the worker ended with exit status " + std::to_string(exit_status);
}

void run_in_workers(int count, int jobs, const ProcessLimits& limits, const std::function<int(int)>& task,
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
      const int i = next;
      const pid_t pid = fork_limited_child(limits, nullptr, [&] { return task(i); });
      if (pid < 0) {
        WorkerOutcome failed;
        failed.not_started = std::strerror(errno);
        done(next++, failed);
        continue;
      }
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
      outcome.status = status;
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
