// Bidirectional layered link-distance search (docs/route-planning.md): the fewest moves between
// two cells over the move graph of the exact search (a move ends on a template end point whose
// supercover line is all kSafe; every move but the last is at least D_min long).
//
// Layer k of a side holds the cells first reached with k moves from its root (the start, or the
// goal, whose first move is the route's last and may be short); layer k+1 is the union of what
// the layer-k cells see. Both sides grow a layer at a time (the smaller frontier first) until a
// meeting proves the fewest moves. Runs are bounded: for B = the geodesic lower bound, B + 1, ...
// a run keeps only cells that can lie on a route of B moves (layer + chamfer bound to the other
// root <= B), so a failed run proves "more than B" cheaply and the first run that meets is
// optimal. Within a run a cell sees nothing new once every cell it could reach is reached or cut:
// every template subtree (a bundle of supercover lines) whose end points' bounding box holds no
// live cell is skipped, and whole cells with it. Live cells are counted in 8 x 8 blocks, so the
// test is conservative (it never skips a new cell).
#include <algorithm>
#include <limits>

#include "planner_internal.hpp"

namespace indoormap::planning::detail {

namespace {

constexpr int kLinkBlockShift = 3;             ///< 8 x 8 cell blocks
constexpr std::int32_t kLinkTestSubtree = 24;  ///< test subtrees of at least this many nodes
constexpr std::int32_t kLinkNone = -1;

/// Bounding box of the end points in each prefix-tree node's subtree (template offsets).
struct LinkBoxes {
  std::vector<std::int16_t> x0, x1, y0, y1;
};

LinkBoxes link_subtree_boxes(const NeighbourhoodTemplate& t) {
  const std::size_t n = t.dx.size();
  LinkBoxes b{std::vector<std::int16_t>(n, std::numeric_limits<std::int16_t>::max()),
              std::vector<std::int16_t>(n, std::numeric_limits<std::int16_t>::min()),
              std::vector<std::int16_t>(n, std::numeric_limits<std::int16_t>::max()),
              std::vector<std::int16_t>(n, std::numeric_limits<std::int16_t>::min())};
  for (std::size_t i = n; i-- > 0;) {
    if (t.end_point[i] >= 0) {
      b.x0[i] = std::min(b.x0[i], t.dx[i]), b.x1[i] = std::max(b.x1[i], t.dx[i]);
      b.y0[i] = std::min(b.y0[i], t.dy[i]), b.y1[i] = std::max(b.y1[i], t.dy[i]);
    }
    for (auto j = i + 1; j < static_cast<std::size_t>(t.skip[i]);
         j = static_cast<std::size_t>(t.skip[j])) {
      b.x0[i] = std::min(b.x0[i], b.x0[j]), b.x1[i] = std::max(b.x1[i], b.x1[j]);
      b.y0[i] = std::min(b.y0[i], b.y0[j]), b.y1[i] = std::max(b.y1[i], b.y1[j]);
    }
  }
  return b;
}

/// One side of the search: the layer of every cell (-1: not reached), its parent towards the
/// side's root, the current frontier layer and the live cells per block (safe, not reached, and
/// still able to lie on a route within the bound).
struct LinkSide {
  std::vector<std::int32_t> layer, parent, frontier;
  std::vector<std::int32_t> alive;
  const std::vector<std::uint16_t>* h = nullptr;  ///< lower bound on the moves to the other root
  int depth = 0;          ///< every cell within `depth` moves (and the bound) is known
  int max_h = 0;          ///< cells with h > max_h cannot be reached usefully any more
  bool backward = false;  ///< rooted at the goal: its first move is the route's last, any length
};

class LinkSearch {
 public:
  LinkSearch(const Grid<SafeCell>& safe, const NeighbourhoodTemplate& t, const PlannerParams& p,
             std::int32_t start, std::int32_t goal)
      : safe_(safe),
        t_(t),
        p_(p),
        start_(start),
        goal_(goal),
        boxes_(link_subtree_boxes(t)),
        h_goal_(moves_bound_from(chamfer_from(safe, {goal % safe.width, goal / safe.width}), t)),
        h_start_(
            moves_bound_from(chamfer_from(safe, {start % safe.width, start / safe.width}), t)) {
    bw_ = (safe.width + 7) >> kLinkBlockShift;
    bh_ = (safe.height + 7) >> kLinkBlockShift;
    fwd_.h = &h_goal_, bwd_.h = &h_start_;
    fwd_.backward = false, bwd_.backward = true;
    for (auto* side : {&fwd_, &bwd_}) {  // cells by bound, for the per-layer cut
      auto& by = side == &fwd_ ? by_h_goal_ : by_h_start_;
      for (std::size_t i = 0; i < safe.size(); ++i) {
        const auto hv = (*side->h)[i];
        if (hv == kNoMovesBound) continue;
        if (hv >= by.size()) by.resize(hv + 1u);
        by[hv].push_back(static_cast<std::int32_t>(i));
      }
    }
  }

  /// Fewest moves, at most `bound` (-1: none, or the budget ran out: res.complete false); the
  /// route's cells (flat indices, start first) in `route`. Iterative deepening on the bound B
  /// from the geodesic lower bound: each failed run proves that no route has B moves.
  int run(int bound, std::vector<std::int32_t>& route, ExactResult& res, SearchBudget& budget) {
    const auto h0 = h_goal_[static_cast<std::size_t>(start_)];
    if (h0 == kNoMovesBound) return -1;
    for (int b = std::max(1, int{h0}); b <= bound; ++b) {
      excluded_ = false;
      const int m = run_bounded(b, route, res, budget);
      if (m >= 0 || !res.complete) return m;
      if (!excluded_) return -1;  // the bound cut nothing: no route at all
    }
    return -1;
  }

 private:
  int run_bounded(int b, std::vector<std::int32_t>& route, ExactResult& res, SearchBudget& budget) {
    bound_ = b;
    best_ = std::numeric_limits<std::int64_t>::max();
    meet_ = kLinkNone;
    init(fwd_, start_);
    init(bwd_, goal_);
    while (true) {
      // The stop (docs/route-planning.md): once the goal side has moved (depth b >= 1), every
      // route of L <= a + b moves has a cell both sides reached, with dF + dB <= L; a side with
      // an empty frontier has reached every cell it can, so every route has been met.
      if (best_ <= bound_) break;  // optimal: every run below b found nothing
      if (bwd_.depth >= 1) {
        if (bound_ + 1 <= std::int64_t{fwd_.depth} + bwd_.depth + 1) break;
        if (fwd_.frontier.empty() || bwd_.frontier.empty()) break;
      }
      LinkSide& s = bwd_.depth == 0 || bwd_.frontier.size() < fwd_.frontier.size() ? bwd_ : fwd_;
      if (!grow(s, s.backward ? fwd_ : bwd_, budget, res)) {
        res.complete = false;
        return -1;
      }
    }
    if (best_ > bound_ || meet_ == kLinkNone) return -1;
    route.clear();
    for (std::int32_t i = meet_; i != kLinkNone; i = fwd_.parent[static_cast<std::size_t>(i)])
      route.push_back(i);
    std::reverse(route.begin(), route.end());
    for (std::int32_t i = bwd_.parent[static_cast<std::size_t>(meet_)]; i != kLinkNone;
         i = bwd_.parent[static_cast<std::size_t>(i)])
      route.push_back(i);
    return static_cast<int>(best_);
  }

  const std::vector<std::vector<std::int32_t>>& by_h(const LinkSide& s) const {
    return s.backward ? by_h_start_ : by_h_goal_;
  }

  void init(LinkSide& s, std::int32_t root) {
    s.layer.assign(safe_.size(), kLinkNone);
    s.parent.assign(safe_.size(), kLinkNone);
    s.alive.assign(static_cast<std::size_t>(bw_) * bh_, 0);
    s.max_h = std::min<int>(bound_ - 1, static_cast<int>(by_h(s).size()) - 1);
    if (static_cast<int>(by_h(s).size()) - 1 > s.max_h) excluded_ = true;
    for (int hv = 0; hv <= s.max_h; ++hv)
      for (const auto i : by_h(s)[static_cast<std::size_t>(hv)])
        if (safe_.data[static_cast<std::size_t>(i)] == SafeCell::kSafe)
          ++s.alive[block(i % safe_.width, i / safe_.width)];
    s.depth = 0;
    reach(s, root, kLinkNone, 0);
    s.frontier.assign(1, root);
  }

  std::size_t block(int c, int r) const {
    return static_cast<std::size_t>(r >> kLinkBlockShift) * static_cast<std::size_t>(bw_) +
           static_cast<std::size_t>(c >> kLinkBlockShift);
  }

  void reach(LinkSide& s, std::int32_t i, std::int32_t from, int layer) {
    const auto u = static_cast<std::size_t>(i);
    s.layer[u] = layer;
    s.parent[u] = from;
    if ((*s.h)[u] <= s.max_h) --s.alive[block(i % safe_.width, i / safe_.width)];
  }

  /// Does the map rectangle [c0, c1] x [r0, r1] (clamped) hold a live cell of `s`?
  bool any_alive(const LinkSide& s, int c0, int c1, int r0, int r1) const {
    c0 = std::max(c0, 0), r0 = std::max(r0, 0);
    c1 = std::min(c1, safe_.width - 1), r1 = std::min(r1, safe_.height - 1);
    if (c0 > c1 || r0 > r1) return false;
    for (int br = r0 >> kLinkBlockShift; br <= (r1 >> kLinkBlockShift); ++br)
      for (int bc = c0 >> kLinkBlockShift; bc <= (c1 >> kLinkBlockShift); ++bc)
        if (s.alive[static_cast<std::size_t>(br) * bw_ + bc] > 0) return true;
    return false;
  }

  /// Expands the frontier layer k of `s` into layer k + 1, whose cells must have h <= B - k - 1
  /// to lie on a route of at most B moves. False when the budget ran out.
  bool grow(LinkSide& s, const LinkSide& other, SearchBudget& budget, ExactResult& res) {
    const int k = s.depth;
    for (; s.max_h > bound_ - k - 1 && s.max_h >= 0; --s.max_h)  // now out of reach
      for (const auto i : by_h(s)[static_cast<std::size_t>(s.max_h)]) {
        excluded_ = true;
        if (s.layer[static_cast<std::size_t>(i)] == kLinkNone &&
            safe_.data[static_cast<std::size_t>(i)] == SafeCell::kSafe)
          --s.alive[block(i % safe_.width, i / safe_.width)];
      }
    std::vector<std::int32_t> next;
    for (const std::int32_t ci : s.frontier) {
      const int c = ci % safe_.width, r = ci / safe_.width;
      const int rad = t_.radius_cells;
      if (!any_alive(s, c - rad, c + rad, r - rad, r + rad)) continue;  // sees nothing new
      if (!budget.spend("min_link", res.nodes)) return false;
      const bool any_length = s.backward && k == 0;  // the route's last move
      walk(s, c, r, any_length, [&](std::int32_t j) {
        if ((*s.h)[static_cast<std::size_t>(j)] > s.max_h) return;  // cut by the bound
        reach(s, j, ci, k + 1);
        next.push_back(j);
        const std::int32_t o = other.layer[static_cast<std::size_t>(j)];
        if (o != kLinkNone && std::int64_t{k} + 1 + o < best_) best_ = k + 1 + o, meet_ = j;
      });
      if (best_ <= bound_) break;  // a route of b moves: done (the layer is left unfinished)
    }
    s.frontier = std::move(next);
    s.depth = k + 1;
    return true;
  }

  /// for_each_visible's template walk from cell (c, r), also skipping every subtree whose end
  /// points' box holds no live cell; calls f(cell) for each visible cell not reached yet (length
  /// >= D_min unless any_length).
  template <class F>
  void walk(const LinkSide& s, int c, int r, bool any_length, F&& f) const {
    const int w = safe_.width, h = safe_.height;
    const std::size_t n = t_.dx.size();
    std::size_t i = 0;
    while (i < n) {
      const int cc = c + t_.dx[i], rr = r + t_.dy[i];
      const auto sk = static_cast<std::size_t>(t_.skip[i]);
      if (cc < 0 || rr < 0 || cc >= w || rr >= h) {
        i = sk;
        continue;
      }
      const std::size_t j = idx(w, {cc, rr});
      if (safe_.data[j] != SafeCell::kSafe ||
          (static_cast<std::int32_t>(sk - i) >= kLinkTestSubtree &&
           !any_alive(s, c + boxes_.x0[i], c + boxes_.x1[i], r + boxes_.y0[i], r + boxes_.y1[i]))) {
        i = sk;
        continue;
      }
      if (const auto e = t_.end_point[i];
          e >= 0 && s.layer[j] == kLinkNone &&
          (any_length || t_.end_points[static_cast<std::size_t>(e)].length_m >= p_.d_min_m))
        f(static_cast<std::int32_t>(j));
      ++i;
    }
  }

  const Grid<SafeCell>& safe_;
  const NeighbourhoodTemplate& t_;
  const PlannerParams& p_;
  std::int32_t start_, goal_;
  LinkBoxes boxes_;
  std::vector<std::uint16_t> h_goal_, h_start_;
  std::vector<std::vector<std::int32_t>> by_h_goal_, by_h_start_;
  int bw_ = 0, bh_ = 0, bound_ = 0;
  LinkSide fwd_, bwd_;
  std::int64_t best_ = std::numeric_limits<std::int64_t>::max();
  std::int32_t meet_ = kLinkNone;
  bool excluded_ = false;  ///< the bound cut a cell in this run (else it was unrestricted)
};

}  // namespace

int layered_fewest_moves(const Grid<SafeCell>& safe, const NeighbourhoodTemplate& t,
                         const PlannerParams& p, std::int32_t start, std::int32_t goal, int bound,
                         std::vector<std::int32_t>& route, ExactResult& res, SearchBudget& budget) {
  LinkSearch search(safe, t, p, start, goal);
  return search.run(bound, route, res, budget);
}

}  // namespace indoormap::planning::detail
