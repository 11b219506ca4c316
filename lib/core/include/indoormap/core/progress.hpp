#pragma once
// Progress of a long library step, reported through a plain callback: no terminal code in lib/.
// The apps render it (apps/common/progress.hpp: a bar on a terminal, a line every few seconds
// otherwise, nothing with -q).
#include <cstdint>
#include <functional>

namespace indoormap {

/// Called with `done` of `total` work units (rays, points, bytes, scans; total 0: unknown) from
/// the thread that does the work. Callers call it every few thousand units, never per point, and
/// once more with done == total at the end. Empty: no progress and no cost.
using ProgressFn = std::function<void(std::int64_t done, std::int64_t total)>;

/// Calls a ProgressFn every `every` units of work: `tick()` per unit costs one increment and one
/// compare. Does nothing when the function is empty.
class ProgressTicker {
 public:
  ProgressTicker(const ProgressFn& fn, std::int64_t total, std::int64_t every)
      : fn_(fn), total_(total), every_(every > 0 ? every : 1), next_(every_) {}
  /// Counts `n` units done.
  void tick(std::int64_t n = 1) {
    done_ += n;
    if (done_ >= next_) {
      next_ = done_ + every_;
      if (fn_) fn_(done_, total_);
    }
  }
  /// Reports the end (done == total when the total is known).
  void finish() {
    if (fn_) fn_(total_ > 0 ? total_ : done_, total_ > 0 ? total_ : done_);
  }

 private:
  const ProgressFn& fn_;
  std::int64_t total_, every_, next_, done_ = 0;
};

}  // namespace indoormap
