// Step 4 of the closure: tracing one ring candidate through M_Lee (opening lines, the Lee wave,
// the backward pass, the closing link over the opening lines).
#include <algorithm>
#include <deque>
#include <unordered_map>

#include "internal.hpp"

namespace indoormap::border {

using namespace detail;

namespace {

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

// The run [x0, x1] of row mid becomes the opening line kOpenStart; the component's 8-neighbours
// of it on one side (row mid - 1) become kOpenEnd; the wave starts on the other side (row
// mid + 1) with distance 1. Returns the start cells of the wave.
std::deque<CellIndex> mark_opening_lines(Grid<std::int32_t>& lee, const BorderComponent& comp,
                                         int mid, int x0, int x1) {
  for (int c = x0; c <= x1; ++c) lee.at(c, mid) = kOpenStart;
  std::deque<CellIndex> queue;
  for (int c = x0 - 1; c <= x1 + 1; ++c) {
    if (lee.contains(c, mid - 1) && lee.at(c, mid - 1) == comp.label) lee.at(c, mid - 1) = kOpenEnd;
    if (lee.contains(c, mid + 1) && lee.at(c, mid + 1) == comp.label) {
      lee.at(c, mid + 1) = 1;
      queue.push_back({c, mid + 1});
    }
  }
  return queue;
}

// Forward pass (Lee wave, 8-connected) over the component's cells. Cells touching kOpenEnd are
// "end of path" cells; the first found has the minimum distance, and the wave stops after its
// level. Returns the end cell (preferring one that touches room space), or nullopt.
std::optional<CellIndex> forward_wave(Grid<std::int32_t>& lee, const BorderComponent& comp,
                                      std::deque<CellIndex> queue) {
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
  return end;
}

// Backward pass: from the end to a start cell (distance 1), one distance down per step,
// preferring cells that touch room space (kRoom) so that the chain hugs the room. Returns the
// path start ... end, or nullopt (cannot happen with a BFS wave).
std::optional<std::vector<CellIndex>> backward_pass(const Grid<std::int32_t>& lee, CellIndex end) {
  std::vector<CellIndex> path{end};
  CellIndex cur = end;
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
    if (!best) return std::nullopt;
    cur = *best;
    path.push_back(cur);
  }
  std::reverse(path.begin(), path.end());  // start ... end
  return path;
}

// Closing: from the end over the kOpenEnd / kOpenStart lines back to the start cell (a tiny
// BFS). Returns the link from the kOpenStart cell next to start back to the kOpenEnd cell next
// to end, or nullopt when the lines do not join them.
std::optional<std::vector<CellIndex>> link_over_lines(const Grid<std::int32_t>& lee, CellIndex end,
                                                      CellIndex start) {
  std::unordered_map<std::int64_t, std::int64_t> parent;  // key = row * width + col
  auto key = [&](CellIndex c) { return std::int64_t{c.row} * lee.width + c.col; };
  std::deque<CellIndex> q;
  for (int k = 0; k < 8; ++k) {
    const CellIndex n{end.col + kDc[k], end.row + kDr[k]};
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
  if (!link_end) return std::nullopt;
  std::vector<CellIndex> link;
  for (std::int64_t k = key(*link_end); k >= 0; k = parent[k])
    link.push_back({static_cast<int>(k % lee.width), static_cast<int>(k / lee.width)});
  return link;
}

RingTrace fail(std::string why) {
  return RingTrace{{}, std::move(why)};
}

}  // namespace

namespace detail {

double chain_signed_area(const std::vector<CellIndex>& chain) {
  double a = 0.0;
  for (std::size_t i = 0, n = chain.size(); i < n; ++i) {
    const auto& u = chain[i];
    const auto& v = chain[(i + 1) % n];
    a += static_cast<double>(u.col) * v.row - static_cast<double>(v.col) * u.row;
  }
  return 0.5 * a;
}

}  // namespace detail

RingTrace trace_ring(Grid<std::int32_t>& lee, const BorderComponent& comp) {
  const int mid = (comp.min.row + comp.max.row) / 2;
  if (mid - 1 < comp.min.row || mid + 1 > comp.max.row) return fail("too flat to hold a ring");
  // The first switch on the mid-line: the run [x0, x1] becomes the opening line.
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
  std::deque<CellIndex> queue = mark_opening_lines(lee, comp, mid, x0, x1);
  if (queue.empty()) return fail("nothing of the ring beside the opening line");
  const std::optional<CellIndex> end = forward_wave(lee, comp, std::move(queue));
  if (!end) return fail("the wave does not come round: the ring is broken");
  const auto path = backward_pass(lee, *end);
  if (!path) return fail("backward pass lost the wave");
  const auto link = link_over_lines(lee, *end, path->front());
  if (!link) return fail("the opening lines do not join the ends of the path");
  std::vector<CellIndex> chain = *path;
  for (auto it = link->rbegin(); it != link->rend(); ++it) chain.push_back(*it);
  chain = make_taut(chain);
  if (chain.size() < 4) return fail("the ring is too small");
  if (chain_signed_area(chain) < 0) std::reverse(chain.begin(), chain.end());
  return RingTrace{std::move(chain), {}};
}

}  // namespace indoormap::border
