#pragma once
// Grouping a triangle mesh's items (its sides, its triangles) by a vertex of each, in parallel: the
// counting sort under side_partners and orient_faces' duplicate test. No hash of vertex tuples is needed.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/worker_threads.hpp"

namespace cadnurbs {

// What an item puts in its vertex's bucket.
struct BucketEntry {
  std::size_t vertex;   // the bucket, < the vertex count
  std::uint64_t value;  // anything the visit needs (an item number, a key)
};

// Takes the counts of vertices and triangles and `per_triangle` items a triangle; entry(t, k) gives
// item k of triangle t. Calls visit(worker, begin, end) once for each vertex with entries, begin .. end
// being its entries' values in increasing order of (t, k) (a stable counting sort), which the visit may
// reorder. The vertices are shared out to worker_threads() threads in ranges (each thread goes through
// all triangles twice and keeps the entries of its own range), so a bucket is always visited whole by one
// thread, vertices of one range in increasing order; worker is that thread's number, 0 .. worker_threads()
// - 1, for the visit's own counts. Memory: two ints per vertex and a value per item.
template <class Entry, class Visit>
void visit_vertex_buckets(std::size_t vertex_count, std::size_t triangle_count, int per_triangle, Entry entry,
                          Visit visit) {
  const int workers = worker_threads();
  std::vector<int> start(vertex_count + 1, 0);  // start[v + 1]: entries up to v, first within a range
  std::vector<int> range_entries(workers, 0);
  on_workers(workers, [&](int w) {
    const auto [first, end] = worker_range(vertex_count, w, workers);
    for (std::size_t t = 0; t < triangle_count; ++t)
      for (int k = 0; k < per_triangle; ++k) {
        const std::size_t v = entry(t, k).vertex;
        if (v >= first && v < end) ++start[v + 1];
      }
    for (std::size_t v = first + 1; v < end; ++v) start[v + 1] += start[v];
    if (end > first) range_entries[w] = start[end];
  });
  std::vector<std::uint64_t> values(triangle_count * static_cast<std::size_t>(per_triangle));
  on_workers(workers, [&](int w) {
    // Named copies, not a structured binding: the lambda below uses them (clang 14, the browser module's
    // compiler, cannot capture bindings).
    const WorkerRange range = worker_range(vertex_count, w, workers);
    const std::size_t first = range.begin, end = range.end;
    int offset = 0;
    for (int before = 0; before < w; ++before) offset += range_entries[before];
    for (std::size_t v = first + 1; v <= end; ++v) start[v] += offset;
    // The range's first bucket starts at the offset: its start[] is the previous range's to write.
    auto bucket_begin = [&](std::size_t v) { return v == first ? offset : start[v]; };
    std::vector<int> next(end - first);
    for (std::size_t v = first; v < end; ++v) next[v - first] = bucket_begin(v);
    for (std::size_t t = 0; t < triangle_count; ++t)
      for (int k = 0; k < per_triangle; ++k) {
        const BucketEntry e = entry(t, k);
        if (e.vertex >= first && e.vertex < end) values[next[e.vertex - first]++] = e.value;
      }
    for (std::size_t v = first; v < end; ++v)
      if (bucket_begin(v) < start[v + 1]) visit(w, values.data() + bucket_begin(v), values.data() + start[v + 1]);
  });
}

}  // namespace cadnurbs
