#include "indoormap/scan_features/segments.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::scan_features {

const char* boundary_name(Boundary b) {
  switch (b) {
    case Boundary::kScanEnd:
      return "scan_end";
    case Boundary::kRupture:
      return "rupture";
    case Boundary::kBreakpoint:
      return "breakpoint";
    case Boundary::kSplit:
      return "split";
  }
  return "?";
}

void SegmentParams::validate() const {
  if (!(lambda_rad > 0.0 && lambda_rad < std::numbers::pi / 2))
    throw UsageError("segments.lambda_rad must be in (0, pi/2), got " + std::to_string(lambda_rad));
  if (!(sigma_r_m >= 0.0 && std::isfinite(sigma_r_m)))
    throw UsageError("segments.sigma_r_m must be >= 0, got " + std::to_string(sigma_r_m));
  if (!(max_range_m >= 0.0 && std::isfinite(max_range_m)))
    throw UsageError("segments.max_range_m must be >= 0 (0: the scan's), got " +
                     std::to_string(max_range_m));
}

double breakpoint_threshold_m(double r_prev_m, double dphi_rad, const SegmentParams& params) {
  if (dphi_rad >= params.lambda_rad) return 0.0;
  return r_prev_m * std::sin(dphi_rad) / std::sin(params.lambda_rad - dphi_rad) +
         3.0 * params.sigma_r_m;
}

namespace {

/// The boundary between two consecutive valid points a, b (beams ia < ib in scan order).
Boundary link(const ScanPoint& a, const ScanPoint& b, bool beams_between, double inc_rad,
              const SegmentParams& params) {
  if (beams_between) return Boundary::kRupture;
  const double d_max = breakpoint_threshold_m(a.range_m, inc_rad, params);
  return (b.p_laser - a.p_laser).norm() > d_max ? Boundary::kBreakpoint : Boundary::kSplit;
}

}  // namespace

Segmentation segment_scan(const laser::LaserScan& scan, const SegmentParams& params) {
  Segmentation out;
  const double max_r =
      params.max_range_m > 0.0 ? std::min(params.max_range_m, scan.max_range_m) : scan.max_range_m;
  const int n = static_cast<int>(scan.size());
  std::vector<ScanPoint> pts;
  pts.reserve(scan.size());
  for (int i = 0; i < n; ++i) {
    const float r = scan.ranges_m[static_cast<std::size_t>(i)];
    if (!(r > 0.0f && r < max_r)) {  // NaN compares false
      ++out.ruptures;
      continue;
    }
    const double a = scan.beam_angle_rad(static_cast<std::size_t>(i));
    pts.push_back({Eigen::Vector2d(r * std::cos(a), r * std::sin(a)), r, i});
  }
  if (pts.empty()) return out;
  const double inc = std::abs(scan.angle_increment_rad);
  out.full_circle = inc * n >= 2.0 * std::numbers::pi - 1e-6;
  const int m = static_cast<int>(pts.size());
  // links[k]: between pts[k] and pts[k + 1] (for a full circle, links[m - 1] closes the seam).
  std::vector<Boundary> links(static_cast<std::size_t>(m), Boundary::kScanEnd);
  for (int k = 0; k + 1 < m; ++k) {
    const auto& a = pts[static_cast<std::size_t>(k)];
    const auto& b = pts[static_cast<std::size_t>(k + 1)];
    links[static_cast<std::size_t>(k)] = link(a, b, b.beam - a.beam > 1, inc, params);
  }
  int start = 0;
  if (out.full_circle && m > 1) {
    const auto& a = pts.back();
    const auto& b = pts.front();
    links.back() = link(a, b, b.beam + n - a.beam > 1, inc, params);
    // Start after a boundary so that no run is cut at the seam (a closed ring stays as it is).
    for (int k = 0; k < m; ++k)
      if (links[static_cast<std::size_t>((k + m - 1) % m)] != Boundary::kSplit) {
        start = k;
        break;
      }
  }
  out.points.reserve(pts.size());
  std::vector<Boundary> rotated_links;
  for (int k = 0; k < m; ++k) {
    out.points.push_back(pts[static_cast<std::size_t>((start + k) % m)]);
    rotated_links.push_back(links[static_cast<std::size_t>((start + k) % m)]);
  }
  const Boundary first_start = out.full_circle && m > 1 ? rotated_links.back() : Boundary::kScanEnd;
  PointRun run{0, 0, first_start == Boundary::kSplit ? Boundary::kScanEnd : first_start,
               Boundary::kScanEnd};
  for (int k = 0; k < m; ++k) {
    const Boundary l = k + 1 < m ? rotated_links[static_cast<std::size_t>(k)] : Boundary::kScanEnd;
    if (l == Boundary::kBreakpoint) ++out.breakpoints;
    if (l == Boundary::kSplit) continue;
    run.last = k;
    run.end = l;
    if (k + 1 == m && out.full_circle && m > 1) run.end = first_start;
    out.runs.push_back(run);
    run = {k + 1, k + 1, l, Boundary::kScanEnd};
  }
  if (out.full_circle && m > 1 && rotated_links.back() == Boundary::kBreakpoint) ++out.breakpoints;
  if (out.runs.back().end == Boundary::kSplit) out.runs.back().end = Boundary::kScanEnd;
  return out;
}

}  // namespace indoormap::scan_features
