#pragma once
// A child process for work that may crash, hang or grow without end, so that it costs the child and not
// the caller: the STEP/IGES wall's reader (walled_read) and the batch workers (batch/worker_pool) are
// both made here. The child is a fork of the caller, in a process group of its own (the caller kills the
// group at its time limit), killed when the caller dies, with stdin, stdout and stderr on /dev/null (the
// caller speaks for it) and limits on its CPU time, address space and core files.
#include <sys/types.h>

#include <functional>
#include <string>

namespace cadnurbs {

struct ProcessLimits {
  double seconds = 120;   // wall time (the caller's to enforce) and CPU time (the kernel's) of the child
  long megabytes = 4096;  // its address space
};

// Flushes the caller's buffered output (the child must not write it again) and forks. The child sets
// itself up as above, runs `keep_fds()` before its standard streams go to /dev/null (to move pipes it
// keeps onto fixed descriptors; it may _exit on failure), sets `limits`, then exits with `body()`'s value
// (1 when it throws). The caller gets the child's pid, its process group already set, or -1 with errno
// when no child could be made. The caller must run one thread: a fork of a threaded process may find
// locks held for ever.
pid_t fork_limited_child(const ProcessLimits& limits, const std::function<void()>& keep_fds,
                         const std::function<int()>& body);

// "SIGSEGV", or "signal N" for one without a name.
std::string signal_name(int signal);

// How a limited child with wait status `status` ended, in the words of the one-line messages: "exceeded
// 120 s" when the caller killed it at its wall-time limit (`timed_out`), "exceeded 120 s of CPU time"
// (SIGXCPU, or the kernel's SIGKILL past the hard CPU limit), "crashed with SIGSEGV" (any other signal);
// "" when it exited (the caller tells what its exit status means).
std::string limited_child_end(int status, bool timed_out, const ProcessLimits& limits);

}  // namespace cadnurbs
