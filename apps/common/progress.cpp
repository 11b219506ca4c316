#include "progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace indoormap::app {
namespace {

using ProgressClock = std::chrono::steady_clock;

/// The line interval (INDOORMAP_PROGRESS_S, default 5 s; garbage or negative: the default).
double progress_interval_s() {
  const char* v = std::getenv("INDOORMAP_PROGRESS_S");
  if (!v || !*v) return 5.0;
  char* end = nullptr;
  const double s = std::strtod(v, &end);
  return (end && *end == '\0' && std::isfinite(s) && s >= 0) ? s : 5.0;
}

/// "1.2 M", "35.0 k", "950": three significant figures at most.
std::string human_count(double v) {
  char buf[32];
  if (v >= 1e9)
    std::snprintf(buf, sizeof buf, "%.1f G", v / 1e9);
  else if (v >= 1e6)
    std::snprintf(buf, sizeof buf, "%.1f M", v / 1e6);
  else if (v >= 1e4)
    std::snprintf(buf, sizeof buf, "%.1f k", v / 1e3);
  else
    std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

std::string human_seconds(double s) {
  char buf[32];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.0f s", std::ceil(s));
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s) / 60,
                  static_cast<int>(s) % 60);
  else
    std::snprintf(buf, sizeof buf, "%d h %02d min", static_cast<int>(s) / 3600,
                  static_cast<int>(s) / 60 % 60);
  return buf;
}

}  // namespace

ProgressMode progress_mode(bool quiet) {
  if (quiet) return ProgressMode::kOff;
  if (const char* v = std::getenv("INDOORMAP_PROGRESS")) {
    if (std::strcmp(v, "off") == 0) return ProgressMode::kOff;
    if (std::strcmp(v, "bar") == 0) return ProgressMode::kBar;
    if (std::strcmp(v, "lines") == 0) return ProgressMode::kLines;
  }
  return ::isatty(STDERR_FILENO) ? ProgressMode::kBar : ProgressMode::kLines;
}

std::string progress_text(const std::string& label, const std::string& unit, ProgressMode mode,
                          std::int64_t done, std::int64_t total, double seconds) {
  const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0.0;
  const bool known = total > 0;
  const double frac = known ? std::min(1.0, static_cast<double>(done) / total) : 0.0;
  std::string left;
  if (known && rate > 0 && done < total)
    left = "about " + human_seconds(static_cast<double>(total - done) / rate) + " left";
  const std::string rate_s = rate > 0 && !unit.empty() ? human_count(rate) + " " + unit + "/s" : "";
  char pct[16];
  std::snprintf(pct, sizeof pct, "%3d%%", static_cast<int>(frac * 100.0));
  if (mode == ProgressMode::kBar) {
    std::string s = label + " ";
    if (known) {
      constexpr int kWidth = 24;
      const int fill = static_cast<int>(frac * kWidth);
      s += "[" + std::string(fill, '=') + (fill < kWidth ? ">" : "") +
           std::string(std::max(0, kWidth - fill - 1), ' ') + "] " + pct;
    } else {
      s += human_count(static_cast<double>(done)) + " " + unit;
    }
    if (!rate_s.empty()) s += "  " + rate_s;
    if (!left.empty()) s += "  " + left;
    return s;
  }
  std::string s = label + ": ";
  if (known)
    s += std::string(pct + (pct[0] == ' ' ? (pct[1] == ' ' ? 2 : 1) : 0)) + " (" +
         human_count(static_cast<double>(done)) + " of " + human_count(static_cast<double>(total)) +
         " " + unit;
  else
    s += human_count(static_cast<double>(done)) + " " + unit + " (";
  if (!rate_s.empty()) s += (known ? ", " : "") + rate_s;
  if (!left.empty()) s += ", " + left;
  s += ")";
  return s;
}

struct ProgressReporter::State {
  std::string label, unit;
  ProgressMode mode = ProgressMode::kOff;
  double interval_s = 5.0;
  ProgressClock::time_point start = ProgressClock::now(), last = start;
  bool drawn = false;     // a bar line is open (needs a newline)
  bool finished = false;  // done == total reported
  std::int64_t last_done = 0;
  std::size_t width = 0;  // of the last bar, to blank what a shorter one leaves

  void draw(std::int64_t done, std::int64_t total, double seconds) {
    const std::string text = progress_text(label, unit, mode, done, total, seconds);
    if (mode == ProgressMode::kBar) {
      const std::size_t pad = width > text.size() ? width - text.size() : 0;
      std::fprintf(stderr, "\r%s%s", text.c_str(), std::string(pad, ' ').c_str());
      width = text.size();
      drawn = true;
    } else {
      std::fprintf(stderr, "%s\n", text.c_str());
    }
    std::fflush(stderr);
  }
  void end_line() {
    if (drawn) std::fputc('\n', stderr);
    drawn = false;
  }
  ~State() { end_line(); }
};

ProgressReporter::ProgressReporter(std::string label, std::string unit, bool quiet) {
  const ProgressMode mode = progress_mode(quiet);
  if (mode == ProgressMode::kOff) return;
  state_ = std::make_shared<State>();
  state_->label = std::move(label);
  state_->unit = std::move(unit);
  state_->mode = mode;
  const double interval = progress_interval_s();
  state_->interval_s = mode == ProgressMode::kBar ? std::min(0.2, interval) : interval;
}

void ProgressReporter::update(std::int64_t done, std::int64_t total) const {
  if (!state_) return;
  State& s = *state_;
  const auto now = ProgressClock::now();
  if (s.finished) {  // a new round of the same step (the next storey): start again
    if (done >= s.last_done) return;
    s.finished = false;
    s.start = s.last = now;
  }
  s.last_done = done;
  const double since_last = std::chrono::duration<double>(now - s.last).count();
  const bool end = total > 0 && done >= total;
  // The end: the bar shows 100 %; a line only when lines were printed (a long step).
  const bool show = since_last >= s.interval_s ||
                    (end && (s.mode == ProgressMode::kBar ? s.drawn : s.last != s.start));
  if (show) {
    s.draw(done, total, std::chrono::duration<double>(now - s.start).count());
    s.last = now;
  }
  if (end) {
    s.finished = true;
    s.end_line();
  }
}

void ProgressReporter::finish() const {
  if (state_) state_->end_line();
}

ProgressFn ProgressReporter::fn() const {
  if (!state_) return {};
  return [self = *this](std::int64_t done, std::int64_t total) { self.update(done, total); };
}

}  // namespace indoormap::app
