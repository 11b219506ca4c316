#pragma once
// Data parallelism for the passes over millions of points or voxels: the range is cut into one
// contiguous part per worker (at most the machine's cores, at most max_workers), each part runs
// on its own thread (the first on the caller's), and every worker's result is returned in part
// order so the caller merges them deterministically: the result never depends on the timing.
#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace indoormap {

/// Workers for n items of which each worker should get at least min_per_worker: 1 to
/// min(max_workers, hardware threads).
inline std::size_t worker_count(std::size_t n, std::size_t min_per_worker,
                                std::size_t max_workers = 8) {
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t by_size =
      std::max<std::size_t>(1, n / std::max<std::size_t>(min_per_worker, 1));
  return std::max<std::size_t>(1, std::min({cores, max_workers, by_size}));
}

/// Runs fn(begin, end) over the parts of [0, n) and returns the parts' results, first part
/// first. An exception in any part is rethrown (the first part's first) after all have ended.
template <typename Fn>
auto parallel_parts(std::size_t n, std::size_t min_per_worker, Fn fn)
    -> std::vector<decltype(fn(std::size_t{}, std::size_t{}))> {
  using R = decltype(fn(std::size_t{}, std::size_t{}));
  const std::size_t w = worker_count(n, min_per_worker);
  std::vector<R> out(w);
  std::vector<std::exception_ptr> errors(w);
  auto run = [&](std::size_t k) {
    try {
      out[k] = fn(n * k / w, n * (k + 1) / w);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t k = 1; k < w; ++k) threads.emplace_back(run, k);
  run(0);
  for (auto& t : threads) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

}  // namespace indoormap
