#pragma once
// How many threads the parallel stages of the normals pipeline (read_stl, side_partners, orient_faces,
// crease_normals) use, and running one task per thread. Each of those stages splits its work so that its
// result does not depend on the count: one thread and many give the same bits.
#include <atomic>
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace cadnurbs {

namespace detail {
inline std::atomic<int> chosen_worker_threads{0};  // 0: not chosen
}  // namespace detail

// The count set by set_worker_threads, else the machine's hardware threads (at least 1).
inline int worker_threads() {
  const int chosen = detail::chosen_worker_threads.load(std::memory_order_relaxed);
  if (chosen > 0) return chosen;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? static_cast<int>(hardware) : 1;
}

// Takes a count; later calls of worker_threads() return it, or the machine's count again when it is below
// 1. For benches and tests that compare thread counts.
inline void set_worker_threads(int count) {
  detail::chosen_worker_threads.store(count > 0 ? count : 0, std::memory_order_relaxed);
}

// Runs task(0), ..., task(count - 1) at once, task(0) on the calling thread, and returns when all have
// finished (when no further thread can be started, the calling thread runs the remaining tasks too). If
// tasks threw, rethrows the exception of the lowest-numbered one: the error that one thread
// working through the tasks in order would have met first.
template <class Task>
void on_workers(int count, Task&& task) {
  std::vector<std::exception_ptr> errors(count > 0 ? count : 0);
  auto run = [&](int w) {
    try {
      task(w);
    } catch (...) {
      errors[w] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  int started = 1;
  try {
    for (; started < count; ++started) threads.emplace_back(run, started);
  } catch (const std::system_error&) {  // no more threads to be had: the calling thread runs the rest
  }
  if (count > 0) run(0);
  for (int w = started; w < count; ++w) run(w);
  for (std::thread& thread : threads) thread.join();
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
}

// The part [begin, end) of 0 .. n that worker w of count takes: equal parts, in order.
struct WorkerRange {
  std::size_t begin, end;
};
inline WorkerRange worker_range(std::size_t n, int w, int count) {
  return {n * static_cast<std::size_t>(w) / static_cast<std::size_t>(count),
          n * static_cast<std::size_t>(w + 1) / static_cast<std::size_t>(count)};
}

}  // namespace cadnurbs
