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
// live cell is skipped, and whole tiles with it. The template is walked once per tile of 64 x 16
// frontier cells, one bit per cell (walk_tile). Live cells are marked per 8 x 8 block, so the
// test is conservative (it never skips a new cell).
#include <algorithm>
#include <bit>
#include <limits>
#include <utility>

#include "link_bits.hpp"
#include "planner_internal.hpp"

namespace indoormap::planning::detail {

namespace {

constexpr int kLinkBlockShift = 3;             ///< 8 x 8 cell blocks
constexpr std::int32_t kLinkTestSubtree = 24;  ///< test subtrees of at least this many nodes
constexpr std::int32_t kLinkNone = -1;
constexpr std::uint8_t kLinkLongEnd = 1, kLinkShortEnd = 2;
constexpr int kLinkTileRows = 16;  ///< rows of a frontier tile (64 columns: one bit word)

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

/// Depth of each prefix-tree node in its depth-first order (the root's children: 1).
std::vector<int> link_node_depths(const NeighbourhoodTemplate& t) {
  std::vector<int> depth(t.dx.size());
  std::vector<std::int32_t> open;  // subtree ends of the node's ancestors
  for (std::size_t i = 0; i < t.dx.size(); ++i) {
    while (!open.empty() && open.back() <= static_cast<std::int32_t>(i)) open.pop_back();
    depth[i] = static_cast<int>(open.size()) + 1;
    open.push_back(t.skip[i]);
  }
  return depth;
}

/// Per prefix-tree node: kLinkLongEnd where it ends a move of at least D_min, kLinkShortEnd where
/// it ends a shorter one (only the route's last move), else 0.
std::vector<std::uint8_t> link_end_kinds(const NeighbourhoodTemplate& t, double d_min_m) {
  std::vector<std::uint8_t> kind(t.dx.size(), 0);
  for (std::size_t i = 0; i < t.dx.size(); ++i)
    if (const auto e = t.end_point[i]; e >= 0)
      kind[i] = t.end_points[static_cast<std::size_t>(e)].length_m >= d_min_m ? kLinkLongEnd
                                                                              : kLinkShortEnd;
  return kind;
}

/// One side of the search: the layer of every cell (-1: not reached), its parent towards the
/// side's root, the current frontier layer and the live cells per block (safe, not reached, and
/// still able to lie on a route within the bound).
struct LinkSide {
  std::vector<std::int32_t> layer, parent, frontier;
  std::vector<std::int32_t> alive;
  std::vector<std::uint64_t> alive_bits;          ///< one bit per block: does it hold a live cell?
  BitRows live;                                   ///< the live cells themselves
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
        depth_(link_node_depths(t)),
        end_kind_(link_end_kinds(t, p.d_min_m)),
        h_goal_(moves_bound_from(chamfer_from(safe, {goal % safe.width, goal / safe.width}), t)),
        h_start_(
            moves_bound_from(chamfer_from(safe, {start % safe.width, start / safe.width}), t)) {
    bw_ = (safe.width + 7) >> kLinkBlockShift;
    bh_ = (safe.height + 7) >> kLinkBlockShift;
    bwords_ = static_cast<std::size_t>((bw_ + 63) / 64);
    safe_bits_ = blank_bits();
    for (int r = 0; r < safe.height; ++r)
      for (int c = 0; c < safe.width; ++c)
        if (safe.at(c, r) == SafeCell::kSafe) safe_bits_.set(c, r);
    const int max_depth = depth_.empty() ? 0 : *std::max_element(depth_.begin(), depth_.end());
    masks_.assign(static_cast<std::size_t>(max_depth + 1) * kLinkTileRows, 0);
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
    s.live = blank_bits();
    s.max_h = std::min<int>(bound_ - 1, static_cast<int>(by_h(s).size()) - 1);
    if (static_cast<int>(by_h(s).size()) - 1 > s.max_h) excluded_ = true;
    for (int hv = 0; hv <= s.max_h; ++hv)
      for (const auto i : by_h(s)[static_cast<std::size_t>(hv)])
        if (safe_.data[static_cast<std::size_t>(i)] == SafeCell::kSafe) {
          ++s.alive[block(i % safe_.width, i / safe_.width)];
          s.live.set(i % safe_.width, i / safe_.width);
        }
    s.alive_bits.assign(static_cast<std::size_t>(bh_) * bwords_, 0);
    for (std::size_t b = 0; b < s.alive.size(); ++b)
      if (s.alive[b] > 0)
        s.alive_bits[b / bw_ * bwords_ + (b % bw_ >> 6)] |= std::uint64_t{1} << (b % bw_ & 63);
    s.depth = 0;
    reach(s, root, kLinkNone, 0);
    s.live.reset(root % safe_.width, root / safe_.width);
    s.frontier.assign(1, root);
  }

  /// All-zero bits of the map, with the margins walk_tile reads.
  BitRows blank_bits() const {
    return BitRows(safe_.width, safe_.height, t_.radius_cells + 64,
                   t_.radius_cells + kLinkTileRows);
  }

  std::size_t block(int c, int r) const {
    return static_cast<std::size_t>(r >> kLinkBlockShift) * static_cast<std::size_t>(bw_) +
           static_cast<std::size_t>(c >> kLinkBlockShift);
  }

  void reach(LinkSide& s, std::int32_t i, std::int32_t from, int layer) {
    const auto u = static_cast<std::size_t>(i);
    s.layer[u] = layer;
    s.parent[u] = from;
    if ((*s.h)[u] <= s.max_h) kill(s, block(i % safe_.width, i / safe_.width));
  }

  /// One live cell of block b less.
  void kill(LinkSide& s, std::size_t b) const {
    if (--s.alive[b] == 0) {
      const std::size_t br = b / static_cast<std::size_t>(bw_),
                        bc = b % static_cast<std::size_t>(bw_);
      s.alive_bits[br * bwords_ + (bc >> 6)] &= ~(std::uint64_t{1} << (bc & 63));
    }
  }

  /// Does the map rectangle [c0, c1] x [r0, r1] (clamped) touch a block holding a live cell of
  /// `s`? A word of block bits at a time.
  bool any_alive(const LinkSide& s, int c0, int c1, int r0, int r1) const {
    c0 = std::max(c0, 0), r0 = std::max(r0, 0);
    c1 = std::min(c1, safe_.width - 1), r1 = std::min(r1, safe_.height - 1);
    if (c0 > c1 || r0 > r1) return false;
    const int b0 = c0 >> kLinkBlockShift, b1 = c1 >> kLinkBlockShift;
    const int w0 = b0 >> 6, w1 = b1 >> 6;
    const std::uint64_t first = ~std::uint64_t{0} << (b0 & 63);
    const std::uint64_t last = ~std::uint64_t{0} >> (63 - (b1 & 63));
    for (int br = r0 >> kLinkBlockShift; br <= (r1 >> kLinkBlockShift); ++br) {
      const std::uint64_t* row = &s.alive_bits[static_cast<std::size_t>(br) * bwords_];
      for (int wi = w0; wi <= w1; ++wi) {
        std::uint64_t m = row[wi];
        if (wi == w0) m &= first;
        if (wi == w1) m &= last;
        if (m != 0) return true;
      }
    }
    return false;
  }

  /// Expands the frontier layer k of `s` into layer k + 1, whose cells must have h <= B - k - 1
  /// to lie on a route of at most B moves. False when the budget ran out. The frontier goes by
  /// tiles of 64 x kLinkTileRows cells, each walking the template once for all its cells.
  bool grow(LinkSide& s, const LinkSide& other, SearchBudget& budget, ExactResult& res) {
    const int k = s.depth;
    for (; s.max_h > bound_ - k - 1 && s.max_h >= 0; --s.max_h)  // now out of reach
      for (const auto i : by_h(s)[static_cast<std::size_t>(s.max_h)]) {
        excluded_ = true;
        if (s.layer[static_cast<std::size_t>(i)] == kLinkNone &&
            safe_.data[static_cast<std::size_t>(i)] == SafeCell::kSafe) {
          kill(s, block(i % safe_.width, i / safe_.width));
          s.live.reset(i % safe_.width, i / safe_.width);
        }
      }
    const int w = safe_.width, tiles_per_row = (w + 63) / 64;
    auto tile_of = [&](std::int32_t i) {
      return (i / w) / kLinkTileRows * tiles_per_row + (i % w) / 64;
    };
    std::sort(s.frontier.begin(), s.frontier.end(),
              [&](std::int32_t a, std::int32_t b) { return tile_of(a) < tile_of(b); });
    const bool any_length = s.backward && k == 0;  // the route's last move
    std::vector<std::int32_t> next;
    for (std::size_t f = 0; f < s.frontier.size();) {
      const int tile = tile_of(s.frontier[f]);
      const int row0 = tile / tiles_per_row * kLinkTileRows, col0 = tile % tiles_per_row * 64;
      std::fill(masks_.begin(), masks_.begin() + kLinkTileRows, 0);
      int cells = 0;
      for (; f < s.frontier.size() && tile_of(s.frontier[f]) == tile; ++f, ++cells) {
        const std::int32_t i = s.frontier[f];
        masks_[static_cast<std::size_t>(i / w - row0)] |= std::uint64_t{1} << (i % w - col0);
      }
      if (!walk_tile(s, col0, row0, any_length, k, [&] {
            for (int c = 0; c < cells; ++c)
              if (!budget.spend("min_link", res.nodes)) return false;
            return true;
          }))
        return false;
      for (const auto& [to, from] : reached_) {
        next.push_back(to);
        const std::int32_t o = other.layer[static_cast<std::size_t>(to)];
        if (o != kLinkNone && std::int64_t{k} + 1 + o < best_) best_ = k + 1 + o, meet_ = to;
      }
      if (best_ <= bound_) break;  // a route of b moves: done (the layer is left unfinished)
    }
    s.frontier = std::move(next);
    s.depth = k + 1;
    return true;
  }

  /// cur[j] = par[j] & window j of `col`, for the kLinkTileRows rows of a tile; their union.
  static std::uint64_t and_rows(const std::uint64_t* __restrict par, std::uint64_t* __restrict cur,
                                BitRows::Column col) {
    std::uint64_t any = 0;
    if (col.s == 0) {
      for (int j = 0; j < kLinkTileRows; ++j) any |= cur[j] = par[j] & col.a[j];
    } else {
      const unsigned s = col.s, t = 64 - col.s;
      for (int j = 0; j < kLinkTileRows; ++j)
        any |= cur[j] = par[j] & ((col.a[j] >> s) | (col.b[j] << t));
    }
    return any;
  }

  /// for_each_visible's template walk from every cell of one tile at once (bit b of masks_[r]:
  /// frontier cell (col0 + b, row0 + r)): a node's mask keeps the cells whose line up to it is all
  /// kSafe, and a subtree is skipped when the mask is empty or its end points' box (over the
  /// mask's cells) holds no live cell. Every visible live end point (length >= D_min unless
  /// any_length) is reached with layer k + 1 and listed in reached_ with its parent. False when
  /// spend() (called once, if the tile sees anything) refuses.
  template <class Spend>
  bool walk_tile(LinkSide& s, int col0, int row0, bool any_length, int k, Spend&& spend) {
    constexpr int R = kLinkTileRows;
    const int rad = t_.radius_cells;
    reached_.clear();
    {
      int lo = R, hi = -1;
      std::uint64_t any = 0;
      for (int r = 0; r < R; ++r)
        if (masks_[static_cast<std::size_t>(r)] != 0)
          lo = std::min(lo, r), hi = r, any |= masks_[static_cast<std::size_t>(r)];
      if (!any_alive(s, col0 + std::countr_zero(any) - rad, col0 + 63 - std::countl_zero(any) + rad,
                     row0 + lo - rad, row0 + hi + rad))
        return true;  // sees nothing new
      if (!spend()) return false;
    }
    const std::size_t n = t_.dx.size();
    std::size_t i = 0;
    while (i < n) {
      const int d = depth_[i], dx = t_.dx[i], dy = t_.dy[i];
      std::uint64_t* cur = &masks_[static_cast<std::size_t>(d) * R];
      const std::uint64_t any = and_rows(&masks_[static_cast<std::size_t>(d - 1) * R], cur,
                                         safe_bits_.column(col0 + dx, row0 + dy));
      const auto sk = static_cast<std::size_t>(t_.skip[i]);
      if (any == 0) {
        i = sk;
        continue;
      }
      int lo = 0, hi = R - 1;
      while (cur[lo] == 0) ++lo;
      while (cur[hi] == 0) --hi;
      if (static_cast<std::int32_t>(sk - i) >= kLinkTestSubtree &&
          !any_alive(s, col0 + std::countr_zero(any) + boxes_.x0[i],
                     col0 + 63 - std::countl_zero(any) + boxes_.x1[i], row0 + lo + boxes_.y0[i],
                     row0 + hi + boxes_.y1[i])) {
        i = sk;
        continue;
      }
      if (end_kind_[i] == kLinkLongEnd || (any_length && end_kind_[i] == kLinkShortEnd))
        for (int r = lo; r <= hi; ++r) {
          std::uint64_t fresh = cur[r] & s.live.window(col0 + dx, row0 + r + dy);
          if (fresh == 0) continue;
          s.live.clear_window(col0 + dx, row0 + r + dy, fresh);
          for (; fresh != 0; fresh &= fresh - 1) {
            const int b = std::countr_zero(fresh);
            const auto to =
                static_cast<std::int32_t>(idx(safe_.width, {col0 + b + dx, row0 + r + dy}));
            const auto from = static_cast<std::int32_t>(idx(safe_.width, {col0 + b, row0 + r}));
            reach(s, to, from, k + 1);
            reached_.push_back({to, from});
          }
        }
      ++i;
    }
    return true;
  }

  const Grid<SafeCell>& safe_;
  const NeighbourhoodTemplate& t_;
  const PlannerParams& p_;
  std::int32_t start_, goal_;
  LinkBoxes boxes_;
  std::vector<std::int32_t> depth_;     ///< depth of each prefix-tree node (root children: 1)
  std::vector<std::uint8_t> end_kind_;  ///< kLinkLongEnd, kLinkShortEnd or 0 per tree node
  BitRows safe_bits_;                   ///< kSafe cells
  std::vector<std::uint64_t> masks_;    ///< walk_tile's masks, kLinkTileRows per tree depth
  std::vector<std::pair<std::int32_t, std::int32_t>> reached_;  ///< (cell, parent) by walk_tile
  std::vector<std::uint16_t> h_goal_, h_start_;
  std::vector<std::vector<std::int32_t>> by_h_goal_, by_h_start_;
  int bw_ = 0, bh_ = 0, bound_ = 0;
  std::size_t bwords_ = 0;  ///< words of block bits per row of blocks
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
