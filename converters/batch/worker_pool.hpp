#pragma once
// Runs tasks in worker processes (converters/limited_child), a given number at a time, each under a
// wall-time, CPU-time and address-space limit, so that a task that crashes, hangs or runs out of memory
// costs its own process only. The caller must run one thread, as `cadnurbs batch` does.
#include <functional>
#include <string>

#include "converters/limited_child.hpp"

namespace cadnurbs {

// How a worker ended.
struct WorkerOutcome {
  int status = 0;            // its wait status
  bool timed_out = false;    // killed at the wall-time limit
  double seconds = 0;        // wall time it ran
  std::string not_started;   // why no worker could be made (fork's error), else ""
  // One line for a record: "" for exit status 0, else "crashed with SIGSEGV", "exceeded 300 s",
  // "exceeded 300 s of CPU time", "the worker ended with exit status N", "no worker could be started
  // (fork: ...)".
  std::string reason(const ProcessLimits& limits) const;
};

// Runs task(i) for i = 0 .. count-1, at most `jobs` at a time, each in its own worker process whose exit
// status is the task's return value. Calls done(i, outcome) in the caller as each ends, in the order they
// end. Returns when all have ended.
void run_in_workers(int count, int jobs, const ProcessLimits& limits, const std::function<int(int)>& task,
                    const std::function<void(int, const WorkerOutcome&)>& done);

}  // namespace cadnurbs
