#pragma once
// Runs tasks in worker processes, a given number at a time, each under a wall-time, CPU-time and
// address-space limit, so that a task that crashes, hangs or runs out of memory costs its own process
// only. A worker is a fork of the caller running the task's function (the caller must run one thread,
// as `cadnurbs batch` does: a fork of a threaded process may find locks held for ever), in a process
// group of its own that is killed whole at the time limit.
#include <functional>
#include <string>
#include <vector>

namespace cadnurbs {

struct WorkerLimits {
  double seconds = 300;   // wall time; CPU time is limited to the same
  long megabytes = 4096;  // address space
};

// How a worker ended.
struct WorkerOutcome {
  int exit_status = -1;   // when it exited, else -1
  int signal = 0;         // the signal that ended it, else 0
  bool timed_out = false; // killed at the wall-time limit
  double seconds = 0;     // wall time it ran
  std::string not_started;  // why no worker could be made (fork's error), else ""
  // One line for a record: "" for exit status 0, else "crashed with SIGSEGV", "exceeded 300 s",
  // "exceeded 300 s of CPU time", "the worker ended with exit status N", "no worker could be started
  // (fork: ...)".
  std::string reason(const WorkerLimits& limits) const;
};

// Runs task(i) for i = 0 .. count-1, at most `jobs` at a time, each in its own worker process whose exit
// status is the task's return value (its stdout and stderr go to /dev/null). Calls done(i, outcome) in the
// caller as each ends, in the order they end. Returns when all have ended.
void run_in_workers(int count, int jobs, const WorkerLimits& limits, const std::function<int(int)>& task,
                    const std::function<void(int, const WorkerOutcome&)>& done);

}  // namespace cadnurbs
