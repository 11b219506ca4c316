#include "indoormap/exploration/frontier.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "indoormap/core/errors.hpp"

namespace indoormap::exploration {

void WfdParams::validate() const {
  if (min_frontier_cells < 1) throw UsageError("wfd: min_frontier_cells must be at least 1");
}

namespace {

// The four lists of the pseudo-code, as bits of one mark per cell.
enum Mark : std::uint8_t {
  kMapOpen = 1,
  kMapClose = 2,
  kFrontierOpen = 4,
  kFrontierClose = 8,
};

// The map with a one-cell border (padding) so that neighbour loops need no bounds checks.
// Classes: 0 unknown, 1 open, 2 obstacle, 3 blacklisted unknown, 4 padding.
struct Padded {
  int w = 0, h = 0;  // padded size
  std::vector<std::uint8_t> cls;
  std::vector<std::uint8_t> mark;
  std::array<std::ptrdiff_t, 8> adj{};

  Padded(const Grid<Cell>& map, const Blacklist& blacklist) : w(map.width + 2), h(map.height + 2) {
    cls.assign(static_cast<std::size_t>(w) * h, 4);
    mark.assign(cls.size(), 0);
    const bool bl = blacklist.width == map.width && blacklist.height == map.height;
    for (int r = 0; r < map.height; ++r) {
      const Cell* in = &map.at(0, r);
      std::uint8_t* out = &cls[index(0, r)];
      for (int c = 0; c < map.width; ++c) {
        const Cell v = in[c];
        out[c] = v == Cell::kFree ? 1 : v == Cell::kUnknown ? 0 : 2;
      }
      if (bl) {
        const std::uint8_t* b = &blacklist.at(0, r);
        for (int c = 0; c < map.width; ++c)
          if (b[c] && out[c] == 0) out[c] = 3;
      }
    }
    adj = {-w - 1, -w, -w + 1, -1, 1, w - 1, w, w + 1};
  }
  std::size_t index(int c, int r) const { return static_cast<std::size_t>(r + 1) * w + (c + 1); }
  CellIndex cell(std::size_t i) const {
    return {static_cast<int>(i % w) - 1, static_cast<int>(i / w) - 1};
  }
  bool has_open_neighbour(std::size_t i) const {
    for (auto d : adj)
      if (cls[i + d] == 1) return true;
    return false;
  }
  bool frontier_point(std::size_t i) const { return cls[i] == 0 && has_open_neighbour(i); }
};

// A FIFO over a vector; every cell is enqueued at most once per queue, so its size is bounded.
struct Queue {
  std::vector<std::uint32_t> items;
  std::size_t head = 0;
  void clear() {
    items.clear();
    head = 0;
  }
  bool empty() const { return head == items.size(); }
  void push(std::size_t i) { items.push_back(static_cast<std::uint32_t>(i)); }
  std::size_t pop() { return items[head++]; }
};

Frontier make_frontier(const Padded& m, const std::vector<std::size_t>& cells,
                       const GridGeometry& g, CellIndex robot) {
  Frontier f;
  f.cells.reserve(cells.size());
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (std::size_t i : cells) {
    const CellIndex c = m.cell(i);
    f.cells.push_back(c);
    const double dc = c.col - robot.col, dr = c.row - robot.row, d = dc * dc + dr * dr;
    if (d < best) {
      best = d;
      f.closest_to_robot = c;
    }
    sum += g.center_of(c);
  }
  f.centroid_m = sum / static_cast<double>(cells.size());
  return f;
}

}  // namespace

bool is_frontier_point(const Grid<Cell>& map, CellIndex c, const Blacklist& blacklist) {
  if (!map.contains(c.col, c.row) || map.at(c) != Cell::kUnknown) return false;
  if (blacklist.width == map.width && blacklist.height == map.height && blacklist.at(c))
    return false;
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc)
      if ((dr || dc) && map.contains(c.col + dc, c.row + dr) &&
          map.at(c.col + dc, c.row + dr) == Cell::kFree)
        return true;
  return false;
}

WfdResult detect_frontiers(const Grid<Cell>& map, const GridGeometry& g, CellIndex robot,
                           const WfdParams& params, const Blacklist& blacklist) {
  params.validate();
  WfdResult out;
  if (!map.contains(robot.col, robot.row)) return out;
  if (map.size() >= (std::size_t{1} << 31)) throw UsageError("wfd: map above 2^31 cells");
  Padded m(map, blacklist);
  Queue qm, qf;
  qm.items.reserve(map.size() / 2);
  std::vector<std::size_t> new_frontier;
  const std::size_t pose = m.index(robot.col, robot.row);
  qm.push(pose);                     // 2
  m.mark[pose] |= kMapOpen;          // 3
  while (!qm.empty()) {              // 4
    const std::size_t p = qm.pop();  // 5
    ++out.outer_dequeued;
    if (m.mark[p] & kMapClose) continue;  // 6-7
    if (m.frontier_point(p)) {            // 8
      qf.clear();                         // 9
      new_frontier.clear();               // 10
      qf.push(p);                         // 11
      m.mark[p] |= kFrontierOpen;         // 12
      while (!qf.empty()) {               // 13
        const std::size_t q = qf.pop();   // 14
        ++out.inner_dequeued;
        if (m.mark[q] & (kMapClose | kFrontierClose)) continue;  // 15-16
        if (m.frontier_point(q)) {                               // 17
          new_frontier.push_back(q);                             // 18
          for (auto d : m.adj) {                                 // 19
            const std::size_t w = q + d;
            if (m.cls[w] == 4) continue;  // padding: outside the map
            if (!(m.mark[w] & (kFrontierOpen | kFrontierClose | kMapClose))) {  // 20
              qf.push(w);                                                       // 21
              m.mark[w] |= kFrontierOpen;                                       // 22
            }
          }
        }
        m.mark[q] |= kFrontierClose;  // 23
      }
      if (new_frontier.size() >= params.min_frontier_cells)  // 24: save data of NewFrontier
        out.frontiers.push_back(make_frontier(m, new_frontier, g, robot));
      for (std::size_t i : new_frontier) m.mark[i] |= kMapClose;
      if (params.stop_at_first && !out.frontiers.empty()) return out;  // the paper's early stop
    }
    // 25-29. When p is open space, every neighbour v has an open-space neighbour (p itself), so
    // the test is needed only around points that are not open.
    const bool p_open = m.cls[p] == 1;
    for (auto d : m.adj) {
      const std::size_t v = p + d;
      if (m.cls[v] == 4 || (m.mark[v] & (kMapOpen | kMapClose))) continue;
      if (p_open || m.has_open_neighbour(v)) {
        qm.push(v);             // 28
        m.mark[v] |= kMapOpen;  // 29
      }
    }
    m.mark[p] |= kMapClose;  // 30
  }
  return out;
}

}  // namespace indoormap::exploration
