#pragma once
// The limits a child process puts on itself before it runs work that may crash, hang or grow without
// end (the STEP/IGES wall's reader, a batch worker).
namespace cadnurbs {

// Sets the calling process's CPU time to `seconds` (rounded up; SIGXCPU then, SIGKILL a second later),
// its address space to `megabytes`, and no core files. For a freshly forked child.
void limit_this_process(double seconds, long megabytes);

}  // namespace cadnurbs
