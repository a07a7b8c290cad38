#include "converters/process_limits.hpp"

#include <sys/resource.h>

#include <cmath>

namespace cadnurbs {

void limit_this_process(double seconds, long megabytes) {
  const rlim_t cpu = static_cast<rlim_t>(std::ceil(seconds));
  const rlimit cpu_limit{cpu, cpu + 1};
  const rlim_t bytes = static_cast<rlim_t>(megabytes) << 20;
  const rlimit memory_limit{bytes, bytes}, no_core{0, 0};
  ::setrlimit(RLIMIT_CPU, &cpu_limit);
  ::setrlimit(RLIMIT_AS, &memory_limit);
  ::setrlimit(RLIMIT_CORE, &no_core);
}

}  // namespace cadnurbs
