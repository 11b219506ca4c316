#pragma once
// The one progress renderer of the apps (Debian 12 packages no C++ progress-bar library).
//
// stderr a terminal: one bar redrawn in place ("\r"), at most 5 times a second:
//   plan-route: search [=========>          ]  47%  1.2 M nodes/s  about 3 s left
// stderr a pipe or file: one line every INDOORMAP_PROGRESS_S seconds (default 5):
//   plan-route: search: 47% (1.9 M of 4.0 M nodes, 1.2 M nodes/s, about 3 s left)
// -q: nothing. A step shorter than the interval prints nothing in line mode. An unknown total
// (0) shows the count and the rate only.
// Environment (documented in docs/progress.md): INDOORMAP_PROGRESS=bar|lines|off overrides the
// isatty choice; INDOORMAP_PROGRESS_S=SECONDS sets the line interval and, when below 0.2, the
// bar's redraw interval too (tests use 0 to see every report of a short step).
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "indoormap/core/progress.hpp"

namespace indoormap::app {

enum class ProgressMode { kOff, kBar, kLines };

/// The mode for stderr: off when quiet, else INDOORMAP_PROGRESS, else bar on a terminal.
ProgressMode progress_mode(bool quiet);

/// Renders the progress of one step ("<prog>: <step>") on stderr; `unit` names the work units
/// ("rays", "nodes", "MB"). Copies share one state. The bar ends its line on done == total or
/// on finish() (also called by the destructor of the last copy).
class ProgressReporter {
 public:
  ProgressReporter(std::string label, std::string unit, bool quiet);
  /// Reports done of total (total 0: unknown); throttled, cheap when nothing is printed.
  void update(std::int64_t done, std::int64_t total) const;
  /// Ends the bar's line (if one is drawn).
  void finish() const;
  /// A ProgressFn feeding this reporter (empty when the mode is off: the library skips the work).
  ProgressFn fn() const;
  bool active() const { return state_ != nullptr; }

 private:
  struct State;
  std::shared_ptr<State> state_;
};

/// One progress line's text (without "\r" or newline), for the renderer and its tests.
std::string progress_text(const std::string& label, const std::string& unit, ProgressMode mode,
                          std::int64_t done, std::int64_t total, double seconds);

}  // namespace indoormap::app
