#include "indoormap/scan_features/lines.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::scan_features {

void LineParams::validate() const {
  auto positive = [](double v, const char* key) {
    if (!(v > 0.0 && std::isfinite(v)))
      throw UsageError(std::string("lines.") + key + " must be positive, got " + std::to_string(v));
  };
  positive(split_distance_m, "split_distance_m");
  positive(merge_distance_m, "merge_distance_m");
  if (min_points < 2) throw UsageError("lines.min_points must be >= 2");
  if (!(min_length_m >= 0.0)) throw UsageError("lines.min_length_m must be >= 0");
}

LineFit fit_tls(std::span<const ScanPoint> points) {
  LineFit f;
  const double n = static_cast<double>(points.size());
  for (const auto& p : points) f.centroid += p.p_laser;
  f.centroid /= n;
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& p : points) {
    const Eigen::Vector2d d = p.p_laser - f.centroid;
    cov += d * d.transpose();
  }
  // Closed form of the 2x2 principal axis (the eigenvector of the larger eigenvalue).
  const double angle = 0.5 * std::atan2(2.0 * cov(0, 1), cov(0, 0) - cov(1, 1));
  f.direction = {std::cos(angle), std::sin(angle)};
  if (f.direction.dot(points.back().p_laser - points.front().p_laser) < 0.0)
    f.direction = -f.direction;
  double sq = 0.0;
  for (const auto& p : points) {
    const double d = f.signed_distance(p.p_laser);
    sq += d * d;
    f.max_m = std::max(f.max_m, std::abs(d));
  }
  f.rms_m = std::sqrt(sq / n);
  return f;
}

std::vector<std::pair<int, int>> split_iepf(std::span<const ScanPoint> points, int first, int last,
                                            double split_distance_m) {
  std::vector<std::pair<int, int>> out;
  std::vector<std::pair<int, int>> stack{{first, last}};
  while (!stack.empty()) {  // depth first, right half pushed first: pieces come out in order
    const auto [a, b] = stack.back();
    stack.pop_back();
    const Eigen::Vector2d pa = points[static_cast<std::size_t>(a)].p_laser;
    const Eigen::Vector2d ab = points[static_cast<std::size_t>(b)].p_laser - pa;
    const double len = ab.norm();
    int worst = -1;
    double worst_d = split_distance_m;
    for (int k = a + 1; k < b; ++k) {
      const Eigen::Vector2d ap = points[static_cast<std::size_t>(k)].p_laser - pa;
      const double d = len > 0.0 ? std::abs(ab.x() * ap.y() - ab.y() * ap.x()) / len : ap.norm();
      if (d > worst_d) worst_d = d, worst = k;
    }
    if (worst < 0) {
      out.emplace_back(a, b);
      continue;
    }
    stack.emplace_back(worst, b);
    stack.emplace_back(a, worst);
  }
  return out;
}

namespace {

std::span<const ScanPoint> range(const Segmentation& seg, int a, int b) {
  return std::span<const ScanPoint>(seg.points)
      .subspan(static_cast<std::size_t>(a), static_cast<std::size_t>(b - a + 1));
}

/// Merges neighbouring pieces while their joint TLS fit stays within the merge thresholds.
std::vector<std::pair<int, int>> merge_pieces(const Segmentation& seg,
                                              std::vector<std::pair<int, int>> pieces,
                                              const LineParams& p) {
  bool merged = true;
  while (merged && pieces.size() > 1) {
    merged = false;
    for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
      auto [a0, a1] = pieces[i];
      auto [b0, b1] = pieces[i + 1];
      // Only the joint fit decides: the direction of a piece of a few points is mostly noise.
      if (fit_tls(range(seg, a0, b1)).max_m > p.merge_distance_m) continue;
      pieces[i] = {a0, b1};
      pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      merged = true;
    }
  }
  return pieces;
}

}  // namespace

std::vector<Line> extract_lines(const Segmentation& seg, const LineParams& params) {
  std::vector<Line> lines;
  for (const PointRun& run : seg.runs) {
    if (run.size() < params.min_points) continue;
    const auto pieces = merge_pieces(
        seg, split_iepf(seg.points, run.first, run.last, params.split_distance_m), params);
    const std::size_t first_of_run = lines.size();
    for (const auto& [a, b] : pieces) {
      if (b - a + 1 < params.min_points) continue;
      Line l;
      l.first = a;
      l.last = b;
      l.fit = fit_tls(range(seg, a, b));
      l.start_laser = l.fit.project(seg.points[static_cast<std::size_t>(a)].p_laser);
      l.end_laser = l.fit.project(seg.points[static_cast<std::size_t>(b)].p_laser);
      if (l.length_m() < params.min_length_m) continue;
      l.start = lines.size() > first_of_run ? Boundary::kSplit : run.start;
      l.end = run.end;
      if (lines.size() > first_of_run) lines.back().end = Boundary::kSplit;
      lines.push_back(l);
    }
  }
  return lines;
}

}  // namespace indoormap::scan_features
