#include "indoormap/border/border.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <unordered_map>

#include "indoormap/core/errors.hpp"
#include "indoormap/layout/pipeline.hpp"

namespace indoormap::border {

namespace {

// M_Lee marks (paper 3.2.C). Component labels run from kFirstLabel downwards; wave distances are
// positive.
constexpr std::int32_t kBorder = -1;
constexpr std::int32_t kOpenStart = -2;  // the opening line the wave must not cross
constexpr std::int32_t kOpenEnd = -3;    // the parallel line that marks the end of the path
constexpr std::int32_t kRoom = -4;
constexpr std::int32_t kVirgin = -5;
constexpr std::int32_t kFirstLabel = -6;

// 8-neighbourhood, orthogonal steps first so that ties prefer them deterministically.
constexpr int kDc[8] = {1, 0, -1, 0, 1, -1, -1, 1};
constexpr int kDr[8] = {0, 1, 0, -1, 1, 1, -1, -1};

bool adjacent8(CellIndex a, CellIndex b) {
  return std::max(std::abs(a.col - b.col), std::abs(a.row - b.row)) == 1;
}

template <class T>
bool has_neighbour(const Grid<T>& g, CellIndex c, T value) {
  for (int k = 0; k < 8; ++k) {
    const int nc = c.col + kDc[k], nr = c.row + kDr[k];
    if (g.contains(nc, nr) && g.at(nc, nr) == value) return true;
  }
  return false;
}

cv::Mat as_mat(Grid<std::uint8_t>& g) {
  return cv::Mat(g.height, g.width, CV_8U, g.data.data());
}

std::string fmt_xy(const Eigen::Vector2d& p) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

// Removes corner cells whose two chain neighbours are 8-neighbours themselves (the chain stays
// closed and 8-connected, only shorter). Cyclic.
std::vector<CellIndex> make_taut(const std::vector<CellIndex>& chain) {
  std::vector<CellIndex> out;
  out.reserve(chain.size());
  for (const auto& c : chain) {
    out.push_back(c);
    while (out.size() >= 3 && adjacent8(out[out.size() - 3], out.back())) out.erase(out.end() - 2);
  }
  // Wrap-around: the corners at the seam.
  bool changed = true;
  while (changed && out.size() > 4) {
    changed = false;
    const std::size_t n = out.size();
    if (adjacent8(out[n - 2], out[0])) {
      out.pop_back();
      changed = true;
    } else if (adjacent8(out[n - 1], out[1])) {
      out.erase(out.begin());
      changed = true;
    }
  }
  return out;
}

double chain_signed_area(const std::vector<CellIndex>& chain) {
  double a = 0.0;
  for (std::size_t i = 0, n = chain.size(); i < n; ++i) {
    const auto& u = chain[i];
    const auto& v = chain[(i + 1) % n];
    a += static_cast<double>(u.col) * v.row - static_cast<double>(v.col) * u.row;
  }
  return 0.5 * a;
}

Polygon cell_polygon(const std::vector<CellIndex>& chain) {
  Polygon p;
  p.reserve(chain.size());
  for (const auto& c : chain) p.emplace_back(c.col, c.row);
  return p;
}

}  // namespace

std::string_view to_string(ComponentKind k) {
  switch (k) {
    case ComponentKind::kRoomBorder:
      return "room_border";
    case ComponentKind::kRing:
      return "ring";
    case ComponentKind::kObject:
      return "object";
  }
  return "invalid";
}

void validate(const BorderParams& p) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError("invalid parameter border." + what);
  };
  auto odd = [](int v) { return v >= 1 && v % 2 == 1 && v <= 99; };
  require(odd(p.dilate_full_size), "dilate_full_size: must be odd, in [1, 99]");
  require(odd(p.dilate_cross_size), "dilate_cross_size: must be odd, in [1, 99]");
  require(odd(p.erode_full_size) && p.erode_full_size >= 3,
          "erode_full_size: must be odd, in [3, 99]");
  require(p.erode_iterations >= 1 && p.erode_iterations <= 20,
          "erode_iterations: must be in [1, 20]");
  require(p.simplify_tolerance_m >= 0 && std::isfinite(p.simplify_tolerance_m),
          "simplify_tolerance_m: must be >= 0");
  require(p.face_snap_max_m >= 0 && p.face_snap_max_m <= 5, "face_snap_max_m: must be in [0, 5] m");
  require(p.shadow_max_m >= 0 && p.shadow_max_m <= 20, "shadow_max_m: must be in [0, 20] m");
  require(p.opening_search_m >= 0 && p.opening_search_m <= 10,
          "opening_search_m: must be in [0, 10] m");
  require(p.opening_min_m >= 0 && std::isfinite(p.opening_min_m), "opening_min_m: must be >= 0");
  require(p.door_min_m > 0 && p.door_min_m <= p.door_max_m && std::isfinite(p.door_max_m),
          "door_min_m / door_max_m: need 0 < door_min_m <= door_max_m");
  require(p.door_clear_height_m > 0 && p.door_clear_height_m <= 10,
          "door_clear_height_m: must be in (0, 10] m");
  require(p.door_probe_m > 0 && p.door_probe_m <= 100, "door_probe_m: must be in (0, 100] m");
  require(p.max_open_fraction > 0 && p.max_open_fraction <= 1,
          "max_open_fraction: must be in (0, 1]");
  require(p.max_cells > 0, "max_cells: must be > 0");
}

Grid<std::uint8_t> heavy_border(const Grid<Cell>& layout, const BorderParams& params) {
  validate(params);
  Grid<std::uint8_t> marked(layout.width, layout.height, 0);
  for (std::size_t i = 0; i < marked.size(); ++i) marked.data[i] = layout.data[i] != Cell::kUnknown;
  Grid<std::uint8_t> heavy(layout.width, layout.height, 0);
  if (layout.width == 0 || layout.height == 0) return heavy;
  // Outside the grid counts as virgin for both operations, so a room touching the map edge (robust
  // bounds crop tightly: the Jacobs room touches it at one corner) still gets a closed band.
  const cv::Scalar outside(0);
  const cv::Mat full_d =
      cv::getStructuringElement(cv::MORPH_RECT, {params.dilate_full_size, params.dilate_full_size});
  const cv::Mat cross = cv::getStructuringElement(
      cv::MORPH_CROSS, {params.dilate_cross_size, params.dilate_cross_size});
  const cv::Mat full_e =
      cv::getStructuringElement(cv::MORPH_RECT, {params.erode_full_size, params.erode_full_size});
  cv::Mat dilated, eroded;
  cv::dilate(as_mat(marked), dilated, full_d, {-1, -1}, 1, cv::BORDER_CONSTANT, outside);
  cv::dilate(dilated, dilated, cross, {-1, -1}, 1, cv::BORDER_CONSTANT, outside);
  cv::erode(dilated, eroded, full_e, {-1, -1}, params.erode_iterations, cv::BORDER_CONSTANT,
            outside);
  cv::Mat ring = dilated & ~eroded;
  cv::Mat dst = as_mat(heavy);
  ring.copyTo(dst);
  for (auto& v : heavy.data) v = v ? 1 : 0;
  return heavy;
}

LeeMarking mark_border_components(const Grid<Cell>& layout, const Grid<std::uint8_t>& heavy) {
  if (layout.width != heavy.width || layout.height != heavy.height)
    throw Error("mark_border_components: layout and heavy border differ in size");
  LeeMarking m;
  m.lee = Grid<std::int32_t>(layout.width, layout.height, kVirgin);
  for (std::size_t i = 0; i < heavy.size(); ++i)
    m.lee.data[i] = heavy.data[i] ? kBorder : (layout.data[i] == Cell::kUnknown ? kVirgin : kRoom);
  if (heavy.size() == 0) return m;

  // 8-connected labelling (OpenCV's two-pass union-find does what the paper describes).
  Grid<std::uint8_t> h = heavy;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(as_mat(h), labels, stats, centroids, 8, CV_32S);
  m.components.resize(static_cast<std::size_t>(std::max(0, n - 1)));
  std::vector<std::uint8_t> seen(m.components.size(), 0);
  for (int r = 0; r < layout.height; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < layout.width; ++c) {
      const int l = row[c];
      if (l == 0) continue;
      m.lee.at(c, r) = kFirstLabel - (l - 1);
      auto& comp = m.components[static_cast<std::size_t>(l - 1)];
      if (!seen[static_cast<std::size_t>(l - 1)]) {
        seen[static_cast<std::size_t>(l - 1)] = 1;
        comp.start = {c, r};
      }
    }
  }
  for (int l = 1; l < n; ++l) {
    auto& comp = m.components[static_cast<std::size_t>(l - 1)];
    comp.label = kFirstLabel - (l - 1);
    comp.min = {stats.at<int>(l, cv::CC_STAT_LEFT), stats.at<int>(l, cv::CC_STAT_TOP)};
    comp.max = {comp.min.col + stats.at<int>(l, cv::CC_STAT_WIDTH) - 1,
                comp.min.row + stats.at<int>(l, cv::CC_STAT_HEIGHT) - 1};
    comp.cells = stats.at<int>(l, cv::CC_STAT_AREA);
    // Switches: runs of the component along the horizontal line halving its bounding box. A ring
    // crosses it at least twice (its two sides); an object once.
    const int mid = (comp.min.row + comp.max.row) / 2;
    bool inside = false;
    for (int c = comp.min.col; c <= comp.max.col; ++c) {
      const bool on = m.lee.at(c, mid) == comp.label;
      if (on && !inside) ++comp.switches;
      inside = on;
    }
    comp.kind = comp.switches >= 2 ? ComponentKind::kRing : ComponentKind::kObject;
  }
  return m;
}

std::optional<std::vector<CellIndex>> trace_ring(Grid<std::int32_t>& lee,
                                                 const BorderComponent& comp, std::string* why) {
  auto fail = [&](const std::string& w) -> std::optional<std::vector<CellIndex>> {
    if (why) *why = w;
    return std::nullopt;
  };
  const int mid = (comp.min.row + comp.max.row) / 2;
  if (mid - 1 < comp.min.row || mid + 1 > comp.max.row) return fail("too flat to hold a ring");
  // The first switch on the mid-line: the run [x0, x1] becomes the opening line -2.
  int x0 = -1, x1 = -1;
  for (int c = comp.min.col; c <= comp.max.col; ++c) {
    if (lee.at(c, mid) == comp.label) {
      if (x0 < 0) x0 = c;
      x1 = c;
    } else if (x0 >= 0) {
      break;
    }
  }
  if (x0 < 0) return fail("no cell on the mid-line");
  for (int c = x0; c <= x1; ++c) lee.at(c, mid) = kOpenStart;
  // -3: the component's 8-neighbours of the -2 line on one side (row mid - 1); the wave starts
  // on the other side (row mid + 1) with distance 1.
  std::deque<CellIndex> queue;
  for (int c = x0 - 1; c <= x1 + 1; ++c) {
    if (lee.contains(c, mid - 1) && lee.at(c, mid - 1) == comp.label) lee.at(c, mid - 1) = kOpenEnd;
    if (lee.contains(c, mid + 1) && lee.at(c, mid + 1) == comp.label) {
      lee.at(c, mid + 1) = 1;
      queue.push_back({c, mid + 1});
    }
  }
  if (queue.empty()) return fail("nothing of the ring beside the opening line");

  // Forward pass (Lee wave, 8-connected) over the component's cells. Cells touching -3 are "end
  // of path" cells; the first found has the minimum distance, and the wave stops after its level.
  std::optional<CellIndex> end;
  bool end_touches_room = false;
  while (!queue.empty()) {
    const CellIndex cur = queue.front();
    queue.pop_front();
    const std::int32_t d = lee.at(cur);
    if (end && d > lee.at(*end)) break;
    if (has_neighbour(lee, cur, kOpenEnd)) {
      const bool room = has_neighbour(lee, cur, kRoom);
      if (!end || (room && !end_touches_room)) {
        end = cur;
        end_touches_room = room;
      }
    }
    for (int k = 0; k < 8; ++k) {
      const int nc = cur.col + kDc[k], nr = cur.row + kDr[k];
      if (!lee.contains(nc, nr) || lee.at(nc, nr) != comp.label) continue;
      lee.at(nc, nr) = d + 1;
      queue.push_back({nc, nr});
    }
  }
  if (!end) return fail("the wave does not come round: the ring is broken");

  // Backward pass: from the end to a start cell (distance 1), one distance down per step,
  // preferring cells that touch room space (-4) so that the chain hugs the room.
  std::vector<CellIndex> path{*end};
  CellIndex cur = *end;
  while (lee.at(cur) > 1) {
    const std::int32_t want = lee.at(cur) - 1;
    std::optional<CellIndex> best;
    bool best_room = false;
    for (int k = 0; k < 8; ++k) {
      const CellIndex n{cur.col + kDc[k], cur.row + kDr[k]};
      if (!lee.contains(n.col, n.row) || lee.at(n) != want) continue;
      const bool room = has_neighbour(lee, n, kRoom);
      if (!best || (room && !best_room)) {
        best = n;
        best_room = room;
      }
    }
    if (!best) return fail("backward pass lost the wave");  // cannot happen with a BFS wave
    cur = *best;
    path.push_back(cur);
  }
  std::reverse(path.begin(), path.end());  // start ... end

  // Closing: from the end over the -3 / -2 lines back to the start cell (a tiny BFS).
  const CellIndex start = path.front();
  std::unordered_map<std::int64_t, std::int64_t> parent;  // key = row * width + col
  auto key = [&](CellIndex c) { return std::int64_t{c.row} * lee.width + c.col; };
  std::deque<CellIndex> q;
  for (int k = 0; k < 8; ++k) {
    const CellIndex n{end->col + kDc[k], end->row + kDr[k]};
    if (!lee.contains(n.col, n.row)) continue;
    const auto v = lee.at(n);
    if ((v == kOpenEnd || v == kOpenStart) && !parent.count(key(n))) {
      parent[key(n)] = -1;
      q.push_back(n);
    }
  }
  std::optional<CellIndex> link_end;
  while (!q.empty() && !link_end) {
    const CellIndex c = q.front();
    q.pop_front();
    if (lee.at(c) == kOpenStart && adjacent8(c, start)) {
      link_end = c;
      break;
    }
    for (int k = 0; k < 8; ++k) {
      const CellIndex n{c.col + kDc[k], c.row + kDr[k]};
      if (!lee.contains(n.col, n.row)) continue;
      const auto v = lee.at(n);
      if ((v == kOpenEnd || v == kOpenStart) && !parent.count(key(n))) {
        parent[key(n)] = key(c);
        q.push_back(n);
      }
    }
  }
  if (!link_end) return fail("the opening lines do not join the ends of the path");
  std::vector<CellIndex> link;
  for (std::int64_t k = key(*link_end); k >= 0; k = parent[k])
    link.push_back({static_cast<int>(k % lee.width), static_cast<int>(k / lee.width)});
  // link runs from the -2 cell next to the start back to the -3 cell next to the end.
  std::vector<CellIndex> chain = path;
  for (auto it = link.rbegin(); it != link.rend(); ++it) chain.push_back(*it);
  chain = make_taut(chain);
  if (chain.size() < 4) return fail("the ring is too small");
  if (chain_signed_area(chain) < 0) std::reverse(chain.begin(), chain.end());
  return chain;
}

namespace {

// The openings of a closed chain: maximal cyclic runs of chain cells with no obstacle within r
// cells, measured between the nearest obstacle cells on either side.
std::vector<Opening> find_openings(const std::vector<CellIndex>& chain, const Grid<Cell>& layout,
                                   const GridGeometry& geo, const BorderParams& params,
                                   const Grid<std::uint8_t>* open_below) {
  std::vector<Opening> out;
  const int r = static_cast<int>(std::lround(params.opening_search_m / geo.cell_m()));
  auto obstacle = [&](int c, int row) {
    if (!layout.contains(c, row)) return false;
    const Cell v = layout.at(c, row);
    if (v != Cell::kWall && v != Cell::kFurniture) return false;
    return !(open_below && open_below->at(c, row));
  };
  auto near_obstacle = [&](CellIndex p, int rad) {
    for (int dr = -rad; dr <= rad; ++dr)
      for (int dc = -rad; dc <= rad; ++dc)
        if (obstacle(p.col + dc, p.row + dr)) return true;
    return false;
  };
  const std::size_t n = chain.size();
  std::vector<std::uint8_t> open(n, 0);
  std::size_t first_closed = n;
  for (std::size_t i = 0; i < n; ++i) {
    open[i] = !near_obstacle(chain[i], r);
    if (!open[i] && first_closed == n) first_closed = i;
  }
  if (first_closed == n) return out;  // no obstacle anywhere along the chain
  auto obstacles_near = [&](CellIndex p, int rad) {
    std::vector<CellIndex> v;
    for (int dr = -rad; dr <= rad; ++dr)
      for (int dc = -rad; dc <= rad; ++dc)
        if (obstacle(p.col + dc, p.row + dr)) v.push_back({p.col + dc, p.row + dr});
    return v;
  };
  // Walk once round the chain starting at a closed cell, so no run wraps the seam.
  for (std::size_t k = 0; k < n;) {
    const std::size_t i = (first_closed + k) % n;
    if (!open[i]) {
      ++k;
      continue;
    }
    std::size_t len = 0;
    while (k + len < n && open[(first_closed + k + len) % n]) ++len;
    const std::size_t first = i, last = (first_closed + k + len - 1) % n;
    const CellIndex before = chain[(first + n - 1) % n], after = chain[(last + 1) % n];
    const auto sa = obstacles_near(before, r + 1), sb = obstacles_near(after, r + 1);
    double best = std::numeric_limits<double>::infinity();
    CellIndex ba{}, bb{};
    for (const auto& a : sa)
      for (const auto& b : sb) {
        const double d = std::hypot(a.col - b.col, a.row - b.row);
        if (d < best) {
          best = d;
          ba = a;
          bb = b;
        }
      }
    k += len;
    if (!std::isfinite(best) || best <= 1.0) continue;
    // From obstacle centre to obstacle centre, less half a cell at each end: the clear width.
    const Eigen::Vector2d ca = geo.center_of(ba), cb = geo.center_of(bb);
    const Eigen::Vector2d u = (cb - ca).normalized();
    Opening o;
    o.a_m = ca + u * (0.5 * geo.cell_m());
    o.b_m = cb - u * (0.5 * geo.cell_m());
    o.width_m = (o.b_m - o.a_m).norm();
    o.chain_first = first;
    o.chain_last = last;
    if (o.width_m < params.opening_min_m) continue;
    o.is_door_candidate =
        o.width_m >= params.door_min_m - 1e-9 && o.width_m <= params.door_max_m + 1e-9;
    out.push_back(o);
  }
  return out;
}

// Moves every edge of a counter-clockwise polygon (cell units, vertices at cell centres) inwards
// to the wall face: the median, over samples along the edge, of the distance to the first
// room-space (free / furniture) cell. Vertices are the intersections of consecutive moved edges
// (or the vertex moved along the mean normal when they are nearly parallel). Returns nullopt when
// the result is not simple.
std::optional<Polygon> snap_to_faces(const Polygon& poly, const Grid<Cell>& layout,
                                     double max_shift) {
  const std::size_t n = poly.size();
  if (n < 3 || max_shift <= 0) return std::nullopt;
  auto room_at = [&](const Eigen::Vector2d& p) {
    const int c = static_cast<int>(std::lround(p.x())), r = static_cast<int>(std::lround(p.y()));
    if (!layout.contains(c, r)) return false;
    const Cell v = layout.at(c, r);
    return v == Cell::kFree || v == Cell::kFurniture;
  };
  constexpr double step = 0.25;
  std::vector<double> shift(n, -1.0), all_hits;
  std::vector<Eigen::Vector2d> normal(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = poly[i], b = poly[(i + 1) % n];
    const Eigen::Vector2d d = b - a;
    const double len = d.norm();
    normal[i] = Eigen::Vector2d(-d.y(), d.x()) / len;  // inward for counter-clockwise order
    std::vector<double> hits;
    const int samples = std::max(1, static_cast<int>(len));
    for (int k = 0; k <= samples; ++k) {
      const double t = 0.15 + 0.7 * k / samples;  // skip the corners
      const Eigen::Vector2d p = a + d * t;
      for (double s = 0.0; s <= max_shift + 1.0; s += step)
        if (room_at(p + normal[i] * s)) {
          // The face is half a cell before the centre of the first room cell; the hit point lies
          // on average a quarter step past the cell boundary.
          hits.push_back(std::max(0.0, s - 0.5 * step));
          break;
        }
    }
    all_hits.insert(all_hits.end(), hits.begin(), hits.end());
    // Short edges (corner chamfers, door jambs) give noisy medians: they take the global one.
    if (hits.size() < 6) continue;
    std::nth_element(hits.begin(), hits.begin() + hits.size() / 2, hits.end());
    shift[i] = std::min(max_shift, hits[hits.size() / 2]);
  }
  if (all_hits.empty()) return std::nullopt;
  std::nth_element(all_hits.begin(), all_hits.begin() + all_hits.size() / 2, all_hits.end());
  const double global = std::min(max_shift, all_hits[all_hits.size() / 2]);
  for (auto& v : shift)
    if (v < 0) v = global;
  Polygon out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t p = (i + n - 1) % n;  // edge p ends at vertex i, edge i starts there
    const Eigen::Vector2d n1 = normal[p], n2 = normal[i];
    const double c = n1.x() * n2.y() - n1.y() * n2.x();
    if (std::abs(c) < 0.2) {
      const Eigen::Vector2d m = (n1 + n2).normalized();
      out[i] = poly[i] + m * (0.5 * (shift[p] + shift[i]));
      continue;
    }
    // Solve n1.x = n1.v + s1 and n2.x = n2.v + s2 for the moved lines through v = poly[i].
    Eigen::Matrix2d A;
    A << n1.x(), n1.y(), n2.x(), n2.y();
    const Eigen::Vector2d rhs(n1.dot(poly[i]) + shift[p], n2.dot(poly[i]) + shift[i]);
    out[i] = A.inverse() * rhs;
    if ((out[i] - poly[i]).norm() > 3.0 * max_shift + 1.0) return std::nullopt;
  }
  // Corner completion: the shortest path cuts every corner of the ring by up to its width, so a
  // room corner becomes a short chamfer edge. A short edge between two longer ones that turn by
  // more than 45 degrees is replaced by the intersection of those two (the wall corner).
  const double chamfer_max = 2.0 * max_shift + 2.0;
  for (bool changed = true; changed && out.size() > 4;) {
    changed = false;
    const std::size_t m = out.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Eigen::Vector2d a = out[(i + m - 1) % m], b = out[i], c = out[(i + 1) % m],
                            d = out[(i + 2) % m];
      const double len = (c - b).norm();
      if (len > chamfer_max || (b - a).norm() < len || (d - c).norm() < len) continue;
      const Eigen::Vector2d u = (b - a).normalized(), v = (d - c).normalized();
      const double cr = u.x() * v.y() - u.y() * v.x();
      if (std::abs(cr) < std::sin(M_PI / 4)) continue;
      const double t = ((c - a).x() * v.y() - (c - a).y() * v.x()) / cr;  // a + u t on line (c, v)
      const Eigen::Vector2d x = a + u * t;
      if ((x - b).norm() > chamfer_max || (x - c).norm() > chamfer_max) continue;
      Polygon trial = out;
      trial[i] = x;
      trial.erase(trial.begin() + static_cast<std::ptrdiff_t>((i + 1) % m));
      if (!is_simple(trial)) continue;
      out = std::move(trial);
      changed = true;
      break;
    }
  }
  if (!is_simple(out) || signed_area(out) <= 0) return std::nullopt;
  return out;
}

// ---- Polygon from the wall faces --------------------------------------------------------------
//
// The wall face lies inside the wall cells that touch room space: a wall cell is marked when a
// point of the face falls in it, so the face runs through those cells and their centres are an
// unbiased sample of it (the room-side cell boundary is half a cell too far in, on average).

struct FacePoint {
  Eigen::Vector2d p;         // wall cell centre (cell units)
  Eigen::Vector2d room_dir;  // unit direction towards its room-space 8-neighbours
};

bool room_space(Cell v) {
  return v == Cell::kFree || v == Cell::kFurniture;
}

// Wall cells with a room-space 4-neighbour inside the box [lo, hi] (cell units, clamped to one
// cell beyond the grid). Cells just outside the grid count as wall cells: the map's robust bounds
// crop the outermost points, so a room touching the map edge has its wall face there.
std::vector<FacePoint> face_points(const Grid<Cell>& layout, const Eigen::Vector2d& lo,
                                   const Eigen::Vector2d& hi) {
  std::vector<FacePoint> out;
  const int c0 = std::max(-1, static_cast<int>(std::floor(lo.x()))),
            r0 = std::max(-1, static_cast<int>(std::floor(lo.y())));
  const int c1 = std::min(layout.width, static_cast<int>(std::ceil(hi.x()))),
            r1 = std::min(layout.height, static_cast<int>(std::ceil(hi.y())));
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      if (layout.contains(c, r) && layout.at(c, r) != Cell::kWall) continue;
      bool touches = false;
      Eigen::Vector2d dir = Eigen::Vector2d::Zero();
      for (int k = 0; k < 8; ++k) {
        const int nc = c + kDc[k], nr = r + kDr[k];
        if (!layout.contains(nc, nr) || !room_space(layout.at(nc, nr))) continue;
        dir += Eigen::Vector2d(kDc[k], kDr[k]).normalized();
        if (k < 4) touches = true;
      }
      if (!touches || dir.squaredNorm() < 1e-12) continue;
      out.push_back({Eigen::Vector2d(c, r), dir.normalized()});
    }
  return out;
}

// A straight wall face: the line through c along the unit vector u (the room lies to its left).
struct FaceLine {
  Eigen::Vector2d c = Eigen::Vector2d::Zero(), u = Eigen::Vector2d::UnitX();
  std::vector<Eigen::Vector2d> inliers;  // the face points it was fitted to (empty: not fitted)
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();  // chain edge
  Eigen::Vector2d normal() const { return {-u.y(), u.x()}; }
  double length() const { return (b - a).norm(); }
};

// Fewer face points beside an edge than this: no line is fitted (the edge has no face of its own).
constexpr std::size_t kMinFacePoints = 4;

// Total least squares line through pts; the direction is oriented along hint.
void fit_tls(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& hint, FaceLine& line) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  double sxx = 0, sxy = 0, syy = 0;
  for (const auto& p : pts) {
    const Eigen::Vector2d d = p - mean;
    sxx += d.x() * d.x();
    sxy += d.x() * d.y();
    syy += d.y() * d.y();
  }
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  Eigen::Vector2d u(std::cos(angle), std::sin(angle));
  if (u.dot(hint) < 0) u = -u;
  line.c = mean;
  line.u = u;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Robust fit of one edge's wall face: the face points beside the edge (from out_reach outside the
// chain to in_reach inside it) whose room lies on the inner side, a median start, then total least
// squares with outliers beyond 2.5 robust sigmas (at least 1 cell) dropped. The direction may turn
// by at most 30 degrees from the edge's; otherwise it keeps the edge's direction.
void fit_edge(const std::vector<FacePoint>& faces, double out_reach, double in_reach,
              FaceLine& line) {
  const Eigen::Vector2d a = line.a, t = (line.b - line.a).normalized();
  const Eigen::Vector2d n(-t.y(), t.x());
  const double len = (line.b - line.a).norm();
  std::vector<Eigen::Vector2d> cand;
  std::vector<double> offs;
  for (const auto& f : faces) {
    const Eigen::Vector2d d = f.p - a;
    const double s = d.dot(t), o = d.dot(n);
    if (s < -1.0 || s > len + 1.0 || o < -out_reach || o > in_reach) continue;
    if (f.room_dir.dot(n) < 0.5) continue;  // the room is not on this edge's inner side
    cand.push_back(f.p);
    offs.push_back(o);
  }
  line.inliers.clear();
  if (cand.size() < kMinFacePoints) return;
  const double o_med = median_of(offs);
  line.u = t;
  line.c = a + n * o_med;
  double th = 2.0;
  for (int iter = 0; iter < 4; ++iter) {
    std::vector<Eigen::Vector2d> in;
    const Eigen::Vector2d ln = line.normal();
    for (const auto& p : cand)
      if (std::abs((p - line.c).dot(ln)) <= th) in.push_back(p);
    if (in.size() < kMinFacePoints) return;
    line.inliers = in;
    fit_tls(in, t, line);
    if (line.u.dot(t) < std::cos(30.0 * M_PI / 180.0)) {  // keep the edge's direction
      line.u = t;
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      for (const auto& p : in) mean += p;
      line.c = mean / static_cast<double>(in.size());
    }
    std::vector<double> r2;
    for (const auto& p : in) r2.push_back(std::abs((p - line.c).dot(line.normal())));
    th = std::max(1.0, 2.5 * 1.4826 * median_of(r2));
  }
}

std::optional<Eigen::Vector2d> intersect(const FaceLine& l1, const FaceLine& l2) {
  const double cr = l1.u.x() * l2.u.y() - l1.u.y() * l2.u.x();
  if (std::abs(cr) < 1e-9) return std::nullopt;
  const Eigen::Vector2d d = l2.c - l1.c;
  const double t = (d.x() * l2.u.y() - d.y() * l2.u.x()) / cr;
  return l1.c + l1.u * t;
}

double angle_between(const FaceLine& l1, const FaceLine& l2) {
  return std::acos(std::clamp(l1.u.dot(l2.u), -1.0, 1.0));
}

// A detour of the chain is taken for the shadow of an object standing in the room when more than
// this share of the cells it cuts off (between the detour and the wall line) is unknown: the
// scanner did not see them. Architecture the chain runs round (a column, a chimney breast) shows
// its faces and the floor beside them; a hollow column, whose inside is unknown too, is told apart
// by its flanks (below).
constexpr double kShadowMinUnknownShare = 0.6;

// [cells] a chain cell this close to a bridged shadow's region runs along it: the region's
// corners are vertices of the chain polygon, which Douglas-Peucker keeps within 1 cell (the
// default simplify_tolerance_m) of the chain, plus half a cell.
constexpr double kShadowChainTol = 1.5;

double distance_to_boundary(const Polygon& poly, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const Eigen::Vector2d a = poly[i], d = poly[(i + 1) % n] - a;
    const double t =
        d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + d * t - p).norm());
  }
  return best;
}

// Whether more than kShadowMinUnknownShare of the cells (cell units: cell (c, r) at (c, r)) inside
// region and on the room side (room_side(p) > 0) are unknown, or off the layout.
template <class RoomSide>
bool mostly_unknown(const Polygon& region, const Grid<Cell>& layout, RoomSide room_side) {
  Eigen::Vector2d lo = region[0], hi = region[0];
  for (const auto& v : region) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  std::int64_t cells = 0, unknown = 0;
  for (int r = static_cast<int>(std::floor(lo.y())); r <= static_cast<int>(std::ceil(hi.y())); ++r)
    for (int c = static_cast<int>(std::floor(lo.x())); c <= static_cast<int>(std::ceil(hi.x()));
         ++c) {
      const Eigen::Vector2d p(c, r);
      if (!(room_side(p) > 0.0) || !contains(region, p)) continue;
      ++cells;
      unknown += !layout.contains(c, r) || layout.at(c, r) == Cell::kUnknown;
    }
  return cells > 0 &&
         static_cast<double>(unknown) > kShadowMinUnknownShare * static_cast<double>(cells);
}

// Whether the chain's detour between lines[i] and lines[i + k] (cyclic, k >= 2; both fitted) is
// the shadow of an object standing in the room, cast on the wall behind it (a pillar 1 m before
// a wall hides a wedge of the floor and of the wall: the wedge is unknown in the layout, and the
// chain runs round it and the object). It is when
//  - the two lines are one straight face: within 8 degrees, and the face points of each lie
//    within tol (cells) of the line fitted to both, on average;
//  - the detour runs into the room (some chain vertex lies more than tol inside that line) and
//    not behind the wall by more than out_max (the chain's usual depth behind the face);
//  - it is at most max_size wide along the line and deep across it;
//  - more than kShadowMinUnknownShare of the cells between the detour and the line are unknown;
//  - its two flanks (the first and the last line of the detour) have fewer than kMinFacePoints
//    face points off the line: a shadow's flanks are rays grazing the object, free space against
//    unknown, while the sides of a column are seen wall faces.
// Returns the line through both faces' points and the region cut off, or nullopt.
struct Shadow {
  FaceLine joint;  // the face line across the shadow
  Polygon region;  // the detour closed along that line (cell units)
};
std::optional<Shadow> shadow_bridge(const std::vector<FaceLine>& lines, std::size_t i,
                                    std::size_t k, const Grid<Cell>& layout, double tol,
                                    double out_max, double max_size) {
  const std::size_t m = lines.size();
  const FaceLine& l1 = lines[i];
  const FaceLine& l2 = lines[(i + k) % m];
  if (angle_between(l1, l2) > 8.0 * M_PI / 180.0) return std::nullopt;
  FaceLine joint = l1;
  joint.b = l2.b;
  joint.inliers.insert(joint.inliers.end(), l2.inliers.begin(), l2.inliers.end());
  fit_tls(joint.inliers, joint.b - joint.a, joint);
  const Eigen::Vector2d n = joint.normal();  // towards the room
  auto offset = [&](const Eigen::Vector2d& p) { return (p - joint.c).dot(n); };
  auto along = [&](const Eigen::Vector2d& p) { return (p - joint.c).dot(joint.u); };
  for (const FaceLine* l : {&l1, &l2}) {
    double mean = 0.0;
    for (const auto& p : l->inliers) mean += offset(p);
    if (std::abs(mean / static_cast<double>(l->inliers.size())) > tol) return std::nullopt;
  }
  // The detour: the chain vertices from the end of l1 to the start of l2.
  Polygon detour{l1.b};
  for (std::size_t q = 1; q < k; ++q) detour.push_back(lines[(i + q) % m].b);
  const double s0 = along(detour.front()), s1 = along(detour.back());
  if (s1 - s0 <= 0.0 || s1 - s0 > max_size) return std::nullopt;
  double deepest = -std::numeric_limits<double>::infinity();
  for (const auto& v : detour) {
    const double o = offset(v), s = along(v);
    if (o < -out_max || o > max_size || s < s0 - out_max || s > s1 + out_max) return std::nullopt;
    deepest = std::max(deepest, o);
  }
  if (deepest <= tol) return std::nullopt;
  // Flanks: face points of the first and the last detour line that are not on the wall line.
  for (const std::size_t q : {std::size_t{1}, k - 1}) {
    std::size_t off = 0;
    for (const auto& p : lines[(i + q) % m].inliers) off += std::abs(offset(p)) > tol;
    if (off >= kMinFacePoints) return std::nullopt;
  }
  // The cells cut off: inside the detour closed along the line, on the room side of the line.
  Polygon region = detour;
  region.push_back(joint.c + joint.u * s1);
  region.push_back(joint.c + joint.u * s0);
  if (!mostly_unknown(region, layout, offset)) return std::nullopt;
  return Shadow{std::move(joint), std::move(region)};
}

// Whether the chain's detour between lines[i] and lines[i + k] (cyclic, k >= 2; both fitted) is
// the shadow of an object standing in the room that hides a convex corner of the room (a pillar
// before a corner, seen from the far side of the room: the corner and the ends of both walls are
// unknown, and the chain cuts across the room round the object). It is when
//  - the two lines turn left (counter-clockwise) by 60 to 120 degrees, and cross at X;
//  - the detour runs from l1's end to l2's start within the corner: each vertex lies no more than
//    out_max behind either line, and X lies at most max_size beyond both ends (along the lines);
//  - the detour runs into the room: some vertex lies more than tol inside both lines;
//  - more than kShadowMinUnknownShare of the cells between the detour and X are unknown;
//  - its two flanks have fewer than kMinFacePoints face points off both lines (as shadow_bridge).
// Returns the corner X and the region cut off (the detour closed through X), or nullopt.
struct CornerShadow {
  Eigen::Vector2d corner = Eigen::Vector2d::Zero();
  Polygon region;  // cell units
};
std::optional<CornerShadow> corner_shadow_bridge(const std::vector<FaceLine>& lines, std::size_t i,
                                                 std::size_t k, const Grid<Cell>& layout,
                                                 double tol, double out_max, double max_size) {
  const std::size_t m = lines.size();
  const FaceLine& l1 = lines[i];
  const FaceLine& l2 = lines[(i + k) % m];
  const double turn = std::atan2(l1.u.x() * l2.u.y() - l1.u.y() * l2.u.x(), l1.u.dot(l2.u));
  if (turn < 60.0 * M_PI / 180.0 || turn > 120.0 * M_PI / 180.0) return std::nullopt;
  const auto x = intersect(l1, l2);
  if (!x) return std::nullopt;
  auto offset = [](const FaceLine& l, const Eigen::Vector2d& p) {
    return (p - l.c).dot(l.normal());
  };
  Polygon detour{l1.b};
  for (std::size_t q = 1; q < k; ++q) detour.push_back(lines[(i + q) % m].b);
  // X beyond both ends: past l1's end along l1, before l2's start along l2.
  const double beyond1 = (*x - detour.front()).dot(l1.u);
  const double beyond2 = (detour.back() - *x).dot(l2.u);
  if (beyond1 < -out_max || beyond1 > max_size || beyond2 < -out_max || beyond2 > max_size)
    return std::nullopt;
  double deepest = -std::numeric_limits<double>::infinity();
  for (const auto& v : detour) {
    const double o1 = offset(l1, v), o2 = offset(l2, v);
    if (o1 < -out_max || o2 < -out_max || o1 > max_size || o2 > max_size) return std::nullopt;
    deepest = std::max(deepest, std::min(o1, o2));
  }
  if (deepest <= tol) return std::nullopt;
  for (const std::size_t q : {std::size_t{1}, k - 1}) {
    std::size_t off = 0;
    for (const auto& p : lines[(i + q) % m].inliers)
      off += std::abs(offset(l1, p)) > tol && std::abs(offset(l2, p)) > tol;
    if (off >= kMinFacePoints) return std::nullopt;
  }
  Polygon region = detour;
  region.push_back(*x);
  if (!mostly_unknown(region, layout, [&](const Eigen::Vector2d& p) {
        return std::min(offset(l1, p), offset(l2, p));
      }))
    return std::nullopt;
  return CornerShadow{*x, std::move(region)};
}

// The polygon from the wall faces (cell units; poly is the simplified counter-clockwise chain
// polygon, which gives the order of the faces):
//  1. every edge of poly is fitted to the face points beside it (fit_edge); an edge without face
//     points (a door's mouth, a gap in the scan) lies at the median depth of the fitted ones;
//  2. consecutive lines of one straight face are merged;
//  3. a bump of at most max_bump cells between two lines of one face (a door recess) is bridged
//     along that face;
//  4. an inward detour of at most max_shadow cells (wide and deep) between two lines of one face
//     round a mostly unknown region is bridged along that face: the shadow of an object standing
//     in the room (shadow_bridge; max_shadow = 0: off); the regions cut off are added to
//     *shadows (when given; also when the fit fails in the end);
//  5. the weakest line its neighbours explain is dropped, so that the neighbours meet at their
//     intersection: the corners the chain cuts (convex or concave), chamfers fitted to the two
//     walls of a corner, wiggles of the chain at windows;
//  6. the vertices are the intersections of consecutive lines (nearly parallel ones, a step in
//     the wall, are joined where the chain joins them).
// nullopt when a corner strays far from the chain, or the result is not simple or not
// counter-clockwise (the caller then falls back to snap_to_faces).
std::optional<Polygon> fit_to_faces(const Polygon& poly, const Grid<Cell>& layout, double max_shift,
                                    double max_bump, double max_shadow,
                                    std::vector<Polygon>* shadows) {
  const std::size_t n0 = poly.size();
  if (n0 < 3 || max_shift <= 0) return std::nullopt;
  const double out_reach = 4.0, in_reach = max_shift + 1.5;
  Eigen::Vector2d lo = poly[0], hi = poly[0];
  for (const auto& v : poly) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const auto faces = face_points(layout, lo.array() - out_reach - 1, hi.array() + out_reach + 1);
  std::vector<FaceLine> lines(n0);
  std::vector<double> depth;
  for (std::size_t i = 0; i < n0; ++i) {
    lines[i].a = poly[i];
    lines[i].b = poly[(i + 1) % n0];
    fit_edge(faces, out_reach, in_reach, lines[i]);
    if (!lines[i].inliers.empty())
      depth.push_back((lines[i].c - lines[i].a).dot(lines[i].normal()));
  }
  if (depth.empty()) return std::nullopt;
  const double global = std::clamp(median_of(depth), 0.0, max_shift);
  for (auto& l : lines)
    if (l.inliers.empty()) {
      l.u = (l.b - l.a).normalized();
      l.c = l.a + l.normal() * global;
    }
  auto supported = [](const FaceLine& l) { return !l.inliers.empty(); };
  auto dist = [](const FaceLine& l, const Eigen::Vector2d& p) {
    return std::abs((p - l.c).dot(l.normal()));
  };
  // One straight face: nearly the same direction and each line through the other's points.
  auto same_face = [&](const FaceLine& l1, const FaceLine& l2) {
    if (angle_between(l1, l2) > 8.0 * M_PI / 180.0) return false;
    return dist(l1, l2.c) <= 1.5 && dist(l2, l1.c) <= 1.5;
  };
  auto refit = [](FaceLine& l) {
    if (l.inliers.size() >= 2) fit_tls(l.inliers, l.b - l.a, l);
  };
  constexpr double kTol = 1.5;  // [cells] a face point this close to a line lies on it
  const double chamfer_max = 2.0 * max_shift + 4.0;
  // Replaces lines[i .. i + k] (cyclic) by joint, which spans from lines[i].a to lines[i + k].b.
  auto join_across = [&](std::size_t i, std::size_t k, FaceLine joint) {
    const std::size_t m = lines.size();
    std::vector<FaceLine> kept;
    for (std::size_t q = 0; q < m; ++q) {
      bool drop = false;
      for (std::size_t d = 1; d <= k; ++d) drop |= q == (i + d) % m;
      if (q == i)
        kept.push_back(std::move(joint));
      else if (!drop)
        kept.push_back(std::move(lines[q]));
    }
    lines = std::move(kept);
  };
  for (bool changed = true; changed && lines.size() > 3;) {
    changed = false;
    const std::size_t m = lines.size();
    // Merge two consecutive fitted lines of one face.
    for (std::size_t i = 0; i < m && !changed; ++i) {
      FaceLine& l1 = lines[i];
      FaceLine& l2 = lines[(i + 1) % m];
      if (!supported(l1) || !supported(l2) || !same_face(l1, l2)) continue;
      l1.b = l2.b;
      l1.inliers.insert(l1.inliers.end(), l2.inliers.begin(), l2.inliers.end());
      refit(l1);
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>((i + 1) % m));
      changed = true;
    }
    if (changed) continue;
    // A bump of the chain between two lines of one face (a door recess without a lintel: the
    // chain runs round the jambs and across the door's mouth): its edges are short or have no
    // face of their own, and the two lines are joined across it. A door recess lies behind the
    // face (the chain crosses the door's mouth where the free space stops, a few cells inside at
    // most); a bump that runs further into the room than the chain's largest depth behind the
    // face (max_shift) is a column standing out of the wall, whose notch stays (or a shadow,
    // below).
    for (std::size_t i = 0; i < m && !changed; ++i) {
      for (std::size_t k = 2; k <= 4 && k + 1 < m && !changed; ++k) {
        const std::size_t j = (i + k) % m;
        if (!supported(lines[i]) || !supported(lines[j]) || !same_face(lines[i], lines[j]))
          continue;
        double span = 0.0;
        bool weak = true, inward = false;
        for (std::size_t q = 1; q < k; ++q) {
          const FaceLine& l = lines[(i + q) % m];
          span += l.length();
          weak &= !supported(l) || l.length() <= chamfer_max;
          inward |= (l.b - lines[i].c).dot(lines[i].normal()) > max_shift;
        }
        if (!weak || inward || span > max_bump) continue;
        FaceLine joint = lines[i];
        joint.b = lines[j].b;
        joint.inliers.insert(joint.inliers.end(), lines[j].inliers.begin(), lines[j].inliers.end());
        refit(joint);
        join_across(i, k, std::move(joint));
        changed = true;
      }
    }
    if (changed) continue;
    // An inward detour of the chain between two lines of one face round the shadow of an object
    // standing in the room (shadow_bridge): the two lines are joined across it. The chain runs
    // behind the face by up to chamfer_max.
    if (max_shadow > 0) {
      for (std::size_t i = 0; i < m && !changed; ++i) {
        if (!supported(lines[i])) continue;
        for (std::size_t k = 2; k + 3 <= m && !changed; ++k) {
          if (!supported(lines[(i + k) % m])) continue;
          if (auto sh = shadow_bridge(lines, i, k, layout, kTol, chamfer_max, max_shadow)) {
            join_across(i, k, std::move(sh->joint));
            if (shadows) shadows->push_back(std::move(sh->region));
            changed = true;
          }
        }
      }
      if (changed) continue;
      // The same round a room's corner: the lines between the two walls are dropped, and the
      // walls meet at their crossing.
      for (std::size_t i = 0; i < m && !changed; ++i) {
        if (!supported(lines[i])) continue;
        for (std::size_t k = 2; k + 2 <= m && !changed; ++k) {
          if (!supported(lines[(i + k) % m])) continue;
          auto sh = corner_shadow_bridge(lines, i, k, layout, kTol, chamfer_max, max_shadow);
          if (!sh) continue;
          lines[i].b = sh->corner;
          lines[(i + k) % m].a = sh->corner;
          std::vector<FaceLine> kept;
          for (std::size_t q = 0; q < m; ++q)
            if ((q + m - i) % m == 0 || (q + m - i) % m >= k) kept.push_back(std::move(lines[q]));
          lines = std::move(kept);
          if (shadows) shadows->push_back(std::move(sh->region));
          changed = true;
        }
      }
      if (changed) continue;
    }
    // Drop the weakest line that its neighbours explain: an unfitted edge between two lines of
    // one face or between two lines meeting near it (a corner the chain cuts, convex or
    // concave); a fitted one whose face points (at least 80 %) lie on its neighbours' lines (a
    // chamfer fitted to the two walls of a corner, a wiggle of the chain at a window).
    std::vector<std::size_t> order(m);
    for (std::size_t i = 0; i < m; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return lines[x].inliers.size() < lines[y].inliers.size();
    });
    for (const std::size_t i : order) {
      FaceLine& prev = lines[(i + m - 1) % m];
      FaceLine& cur = lines[i];
      FaceLine& next = lines[(i + 1) % m];
      const bool parallel = angle_between(prev, next) < 10.0 * M_PI / 180.0;
      if (parallel && !same_face(prev, next)) continue;  // a step: cur joins the two faces
      if (!parallel) {
        const auto x = intersect(prev, next);
        if (!x || (*x - cur.a).norm() > chamfer_max || (*x - cur.b).norm() > chamfer_max) continue;
      }
      if (supported(cur)) {
        if (cur.inliers.size() > std::min(prev.inliers.size(), next.inliers.size())) continue;
        std::size_t explained = 0;
        for (const auto& p : cur.inliers)
          explained += std::min(dist(prev, p), dist(next, p)) <= kTol;
        if (explained < 0.8 * static_cast<double>(cur.inliers.size())) continue;
        for (const auto& p : cur.inliers) {
          if (dist(prev, p) <= dist(next, p)) {
            if (dist(prev, p) <= kTol) prev.inliers.push_back(p);
          } else if (dist(next, p) <= kTol) {
            next.inliers.push_back(p);
          }
        }
        if (supported(prev)) refit(prev);
        if (supported(next)) refit(next);
      }
      prev.b = cur.b;  // the chain edge of prev now reaches over cur's
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
      changed = true;
      break;
    }
  }
  // Corners. A line whose two corners come out in reverse order along it (a short line at a
  // corner whose neighbours cross before reaching it) is dropped, and the corners recomputed.
  Polygon out;
  while (lines.size() >= 3) {
    const std::size_t m = lines.size();
    std::vector<Eigen::Vector2d> start(m), end(m);
    std::vector<std::uint8_t> step(m, 0);  // 1: lines[i - 1] and lines[i] are joined by a step
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t p = (i + m - 1) % m;
      const FaceLine& prev = lines[p];
      const FaceLine& cur = lines[i];
      const auto x = intersect(prev, cur);
      if (!x || angle_between(prev, cur) < 10.0 * M_PI / 180.0) {
        // Nearly parallel neighbours (a step in the wall): joined where the chain joins them.
        end[p] = prev.c + prev.u * (prev.b - prev.c).dot(prev.u);
        start[i] = cur.c + cur.u * (cur.a - cur.c).dot(cur.u);
        step[i] = 1;
        continue;
      }
      if ((*x - cur.a).norm() > 2.0 * chamfer_max) return std::nullopt;
      end[p] = start[i] = *x;
    }
    std::optional<std::size_t> reversed;
    for (std::size_t i = 0; i < m; ++i)
      if ((end[i] - start[i]).dot(lines[i].u) < 0 &&
          (!reversed || lines[i].inliers.size() < lines[*reversed].inliers.size()))
        reversed = i;
    if (!reversed) {
      for (std::size_t i = 0; i < m; ++i) {
        if (step[i]) out.push_back(end[(i + m - 1) % m]);
        out.push_back(start[i]);
      }
      break;
    }
    lines[(*reversed + m - 1) % m].b = lines[*reversed].b;
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(*reversed));
  }
  // Drop repeated vertices.
  Polygon clean;
  for (const auto& v : out)
    if (clean.empty() || (v - clean.back()).norm() > 1e-6) clean.push_back(v);
  while (clean.size() > 1 && (clean.front() - clean.back()).norm() <= 1e-6) clean.pop_back();
  for (const auto& v : clean)
    if (!v.allFinite()) return std::nullopt;
  if (clean.size() < 3 || !is_simple(clean) || !(signed_area(clean) > 0)) return std::nullopt;
  return clean;
}

}  // namespace

BorderResult close_border(const Grid<Cell>& layout, const GridGeometry& geo,
                          const std::vector<Eigen::Vector2d>& scanners_map,
                          const BorderParams& params, const Grid<std::uint8_t>* open_below) {
  validate(params);
  if (layout.width != geo.width() || layout.height != geo.height() ||
      layout.size() !=
          static_cast<std::size_t>(layout.width) * static_cast<std::size_t>(layout.height))
    throw Error("close_border: layout and geometry differ in size");
  if (open_below && (open_below->width != layout.width || open_below->height != layout.height))
    throw Error("close_border: open_below mask and layout differ in size");
  if (geo.cell_count() > params.max_cells)
    throw BudgetError("close_border: layout of " + std::to_string(geo.cell_count()) +
                      " cells exceeds border.max_cells = " + std::to_string(params.max_cells));

  BorderResult res;
  res.heavy = heavy_border(layout, params);
  LeeMarking mk = mark_border_components(layout, res.heavy);
  res.lee = std::move(mk.lee);
  res.components = std::move(mk.components);

  std::vector<std::size_t> rings;
  for (std::size_t i = 0; i < res.components.size(); ++i) {
    auto& comp = res.components[i];
    if (comp.kind != ComponentKind::kRing) continue;
    std::string why;
    if (auto chain = trace_ring(res.lee, comp, &why)) {
      comp.chain = std::move(*chain);
      rings.push_back(i);
    } else {
      comp.kind = ComponentKind::kObject;
      comp.note = why;
    }
  }

  // The room border: the smallest ring whose polygon contains a scanner (paper, section 4).
  auto to_cell_units = [&](const Eigen::Vector2d& p) -> Eigen::Vector2d {
    return (p - geo.origin_m()) / geo.cell_m() - Eigen::Vector2d(0.5, 0.5);
  };
  int room = -1;
  for (const auto& s : scanners_map) {
    double best_area = std::numeric_limits<double>::infinity();
    for (const auto i : rings) {
      const Polygon poly = cell_polygon(res.components[i].chain);
      if (!contains(poly, to_cell_units(s))) continue;
      const double a = std::abs(signed_area(poly));
      if (a < best_area) {
        best_area = a;
        room = static_cast<int>(i);
      }
    }
    if (room >= 0) {
      res.scanner_m = s;
      break;
    }
  }
  if (scanners_map.empty() && !rings.empty()) {
    double best_area = -1.0;
    for (const auto i : rings) {
      const double a = std::abs(chain_signed_area(res.components[i].chain));
      if (a > best_area) {
        best_area = a;
        room = static_cast<int>(i);
      }
    }
    res.warnings.push_back("no scanner position: the largest closed border was taken as the room");
  }

  for (std::size_t i = 0; i < res.components.size(); ++i) {
    auto& comp = res.components[i];
    if (static_cast<int>(i) == room) {
      comp.kind = ComponentKind::kRoomBorder;
      continue;
    }
    InteriorObject o;
    o.min = comp.min;
    o.max = comp.max;
    o.min_m = geo.center_of(comp.min) - Eigen::Vector2d::Constant(0.5 * geo.cell_m());
    o.max_m = geo.center_of(comp.max) + Eigen::Vector2d::Constant(0.5 * geo.cell_m());
    o.cells = comp.cells;
    o.kind = comp.kind;
    res.interior_objects.push_back(o);
  }

  if (room < 0) {
    if (res.components.empty())
      res.reason = "no border: the layout has no marked cells";
    else if (rings.empty())
      res.reason =
          "the border is open: none of the " + std::to_string(res.components.size()) +
          " border components closes into a ring (a gap wider than the morphology bridges)";
    else
      res.reason = "none of the " + std::to_string(rings.size()) +
                   " closed borders contains the scanner at " + fmt_xy(scanners_map.front());
    return res;
  }

  res.closed = true;
  res.room_component = room;
  res.chain = res.components[static_cast<std::size_t>(room)].chain;
  res.chain_m.reserve(res.chain.size());
  for (const auto& c : res.chain) res.chain_m.push_back(geo.center_of(c));

  // Polygon: simplified in cell units; a simplification that self-intersects is retried with
  // half the tolerance, down to the raw chain (which is simple).
  const Polygon raw = cell_polygon(res.chain);
  Polygon poly = raw;
  for (double tol = params.simplify_tolerance_m / geo.cell_m(); tol >= 0.25; tol *= 0.5) {
    Polygon s = simplify_closed(raw, tol);
    if (is_simple(s)) {
      poly = std::move(s);
      break;
    }
  }
  if (signed_area(poly) < 0) std::reverse(poly.begin(), poly.end());
  auto to_map = [&](const Polygon& p) {
    Polygon q;
    for (const auto& v : p)
      q.push_back(geo.origin_m() + (v + Eigen::Vector2d(0.5, 0.5)) * geo.cell_m());
    return q;
  };
  res.chain_polygon_m = to_map(poly);
  res.polygon_m = res.chain_polygon_m;
  std::vector<Polygon> shadows;  // cell units: the shadows polygon_m runs across
  if (params.face_snap_max_m > 0) {
    // A door recess spans the door and its two jambs (each up to the largest move).
    const double max_bump = (params.door_max_m + 2.0 * params.face_snap_max_m) / geo.cell_m() + 4.0;
    if (auto fitted = fit_to_faces(poly, layout, params.face_snap_max_m / geo.cell_m(), max_bump,
                                   params.shadow_max_m / geo.cell_m(), &shadows)) {
      res.polygon_m = to_map(*fitted);
    } else {
      shadows.clear();  // the fallbacks follow the chain round every shadow
      if (auto snapped = snap_to_faces(poly, layout, params.face_snap_max_m / geo.cell_m())) {
        res.polygon_m = to_map(*snapped);
        res.warnings.push_back(
            "the polygon could not be fitted to the wall faces; its edges were moved to them");
      } else {
        res.warnings.push_back(
            "the polygon could not be moved to the wall faces; it follows the chain");
      }
    }
  }
  res.area_m2 = signed_area(res.polygon_m);
  res.perimeter_m = perimeter(res.polygon_m);
  res.openings = find_openings(res.chain, layout, geo, params, open_below);
  // An opening that runs along a shadow the polygon bridged (every chain cell of it on the
  // shadow's region, within kShadowChainTol) is no gap in the room's border but the edge of what
  // an object in the room hid from the scanner; it is dropped.
  std::erase_if(res.openings, [&](const Opening& o) {
    for (const auto& region : shadows) {
      bool all = true;
      for (std::size_t i = o.chain_first;; i = (i + 1) % res.chain.size()) {
        const Eigen::Vector2d p(res.chain[i].col, res.chain[i].row);
        all &= contains(region, p) || distance_to_boundary(region, p) <= kShadowChainTol;
        if (!all || i == o.chain_last) break;
      }
      if (all) return true;
    }
    return false;
  });
  // The morphology closes a band around any marked region, so an open scan (free space running
  // out of the data) still yields a ring; it is recognised by how much of it has no obstacle.
  // Length along the chain (not the chord) of the open runs, against the chain's length.
  double open_m = 0.0, chain_len = 0.0;
  const std::size_t n = res.chain_m.size();
  for (std::size_t i = 0; i < n; ++i)
    chain_len += (res.chain_m[(i + 1) % n] - res.chain_m[i]).norm();
  for (const auto& o : res.openings)
    for (std::size_t i = o.chain_first; i != o.chain_last; i = (i + 1) % n)
      open_m += (res.chain_m[(i + 1) % n] - res.chain_m[i]).norm();
  if (chain_len > 0 && open_m > params.max_open_fraction * chain_len) {
    res.closed = false;
    std::ostringstream why;
    why.precision(0);
    why << std::fixed << "the border is open: " << 100.0 * open_m / chain_len
        << " % of its length has no wall or furniture (border.max_open_fraction = "
        << 100.0 * params.max_open_fraction << " %)";
    res.reason = why.str();
  }
  return res;
}

Grid<std::uint8_t> open_below_mask(const layout::MapResult& m,
                                   const std::vector<Eigen::Vector2d>& scanners_map,
                                   const BorderParams& params) {
  const auto& lay = m.layout.layout;
  Grid<std::uint8_t> mask(lay.width, lay.height, 0);
  const auto& vx = m.voxels;
  if (vx.nx != lay.width || vx.ny != lay.height || vx.nz <= 0 || vx.counts.empty() ||
      scanners_map.empty())
    return mask;
  auto layer_of = [&](double z) { return vx.layer_of(z); };
  // Empty below: no point from the furniture band's bottom to the door height.
  const std::int64_t lo = std::max<std::int64_t>(0, m.layers.furniture_band.lo_layer);
  const std::int64_t hi =
      std::min<std::int64_t>(vx.nz - 1, layer_of(m.layers.floor_z_m + params.door_clear_height_m));
  // Seen beyond: any point from just below the floor to the door height (the floor or the far
  // wall of a corridor seen through the door).
  const std::int64_t see_lo = std::max<std::int64_t>(0, layer_of(m.layers.floor_z_m) - 1);
  if (hi < lo) return mask;
  auto column_has_points = [&](int c, int r, std::int64_t z0, std::int64_t z1) {
    for (std::int64_t z = z0; z <= z1; ++z)
      if (vx.count(c, r, z) > 0) return true;
    return false;
  };
  const GridGeometry& geo = m.geometry;
  const int probe = std::max(2, static_cast<int>(std::lround(params.door_probe_m / geo.cell_m())));
  for (int r = 0; r < lay.height; ++r)
    for (int c = 0; c < lay.width; ++c) {
      const Cell v = lay.at(c, r);
      if (v != Cell::kWall && v != Cell::kFurniture) continue;
      if (column_has_points(c, r, lo, hi)) continue;
      // Empty below can also mean hidden (the foot of a wall behind a cabinet). A door is seen
      // through: along a scanner's ray, beyond the cell, there are points below door height.
      const Eigen::Vector2d p = geo.center_of({c, r});
      bool seen_through = false;
      for (const auto& s : scanners_map) {
        const Eigen::Vector2d d = p - s;
        const double len = d.norm() / geo.cell_m();
        if (len < 1.0) continue;
        const Eigen::Vector2d step = d / len;  // one cell length per step, map metres
        for (int k = 2; k <= probe && !seen_through; ++k) {
          const CellIndex q = geo.cell_of(p + step * k);
          if (!lay.contains(q.col, q.row)) break;
          if (column_has_points(q.col, q.row, see_lo, hi)) seen_through = true;
        }
        if (seen_through) break;
      }
      mask.at(c, r) = seen_through ? 1 : 0;
    }
  return mask;
}

BorderResult close_border(const layout::MapResult& m, const BorderParams& params) {
  validate(params);
  std::vector<Eigen::Vector2d> scanners;
  for (const auto& s : m.cloud_map.scanners) scanners.emplace_back(s.x(), s.y());
  if (scanners.empty())
    for (const auto& s : m.layout.seeds) scanners.push_back(m.geometry.center_of(s));
  const Grid<std::uint8_t> below = open_below_mask(m, scanners, params);
  return close_border(m.layout.layout, m.geometry, scanners, params, &below);
}

}  // namespace indoormap::border
