// parallel_parts (core/parallel.hpp): the parts cover the range once, in order, whatever the
// number of workers; results come back in part order; an exception in a worker reaches the caller.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "indoormap/core/parallel.hpp"

using indoormap::parallel_parts;
using indoormap::worker_count;

TEST(Parallel, PartsCoverTheRangeOnceInOrder) {
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{100'003}}) {
    std::vector<int> seen(n, 0);
    const auto parts = parallel_parts(n, 10, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) ++seen[i];
      return std::pair{b, e};
    });
    ASSERT_FALSE(parts.empty());
    EXPECT_EQ(parts.front().first, 0u);
    EXPECT_EQ(parts.back().second, n);
    for (std::size_t k = 1; k < parts.size(); ++k) EXPECT_EQ(parts[k].first, parts[k - 1].second);
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i], 1) << i;
  }
}

TEST(Parallel, SumsAgreeWithTheSerialSumAndSmallRangesStayOnOneWorker) {
  std::vector<std::uint64_t> v(1'000'000);
  std::iota(v.begin(), v.end(), 1);
  const auto parts = parallel_parts(v.size(), 1000, [&](std::size_t b, std::size_t e) {
    return std::accumulate(v.begin() + b, v.begin() + e, std::uint64_t{0});
  });
  EXPECT_EQ(std::accumulate(parts.begin(), parts.end(), std::uint64_t{0}),
            std::uint64_t{1'000'000} * 1'000'001 / 2);
  EXPECT_EQ(worker_count(999, 1000), 1u) << "fewer items than one worker's minimum";
  EXPECT_GE(worker_count(1 << 30, 1), 1u);
  EXPECT_LE(worker_count(1 << 30, 1, 2), 2u);
}

TEST(Parallel, AnExceptionInAWorkerReachesTheCaller) {
  EXPECT_THROW(parallel_parts(100'000, 10,
                              [](std::size_t b, std::size_t) -> int {
                                (void)b;
                                throw std::runtime_error("part failed");
                                return 0;
                              }),
               std::runtime_error);
}
