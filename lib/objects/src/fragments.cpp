// Fragments of one piece of furniture joined into their object (issue 17): shadows, the height
// rule and a lamp above cut a desk into pieces a cell or two apart; what no object takes is left
// over (counted in the result, not listed).
#include <algorithm>
#include <cmath>
#include <map>

#include "objects_internal.hpp"

namespace indoormap::objects::detail {

namespace {

int fragments_find(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Median of the known values (tops, bottoms) of each label (NaN when none is known).
std::vector<double> fragments_medians(const Labels& lab, const Grid<float>& top) {
  std::vector<std::vector<float>> tops(static_cast<std::size_t>(lab.count) + 1);
  for (std::size_t i = 0; i < lab.labels.size(); ++i)
    if (lab.labels.data[i] && !std::isnan(top.data[i]))
      tops[lab.labels.data[i]].push_back(top.data[i]);
  std::vector<double> med(tops.size(), kNoHeight);
  for (std::size_t k = 1; k < tops.size(); ++k) {
    auto& t = tops[k];
    if (t.empty()) continue;
    std::nth_element(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(t.size() / 2), t.end());
    med[k] = t[t.size() / 2];
  }
  return med;
}

// Pairs of labels whose cells come within gap_cells empty cells of each other (Chebyshev), with
// the number of cell pairs that close (the strength of the contact).
std::map<std::pair<int, int>, std::int64_t> fragments_near_pairs(const Labels& lab, int gap_cells) {
  std::map<std::pair<int, int>, std::int64_t> near;
  const Grid<std::int32_t>& g = lab.labels;
  const int reach = gap_cells + 1;
  for (int r = 0; r < g.height; ++r)
    for (int c = 0; c < g.width; ++c) {
      const int a = g.at(c, r);
      if (!a) continue;
      // Forward half of the neighbourhood only: every unordered cell pair is seen once.
      for (int dr = 0; dr <= reach; ++dr)
        for (int dc = -reach; dc <= reach; ++dc) {
          if (dr == 0 && dc <= 0) continue;
          if (!g.contains(c + dc, r + dr)) continue;
          const int b = g.at(c + dc, r + dr);
          if (b && b != a) ++near[{std::min(a, b), std::max(a, b)}];
        }
    }
  return near;
}

// Two pieces of at least the minimum area whose cells come within the gap at fewer cell pairs
// than this meet at a corner: two shelves end to end along a rotated wall, the floor seen between
// them, touch at one or two cells of the grid's staircase. A shadow or a missed row of samples
// cuts a piece across its width, and a backrest rests on its seat along its length: tens of pairs.
constexpr std::int64_t kMinContactPairs = 3;

}  // namespace

Labels join_fragments(const Labels& in, const PieceHeights& heights, double cell_m,
                      const ObjectParams& params) {
  const int n = in.count;
  if (n < 2 || params.join_gap_m <= 0) return in;
  const int gap = static_cast<int>(std::floor(params.join_gap_m / cell_m + 1e-6));
  const auto min_cells =
      static_cast<std::int64_t>(std::ceil(params.min_area_m2 / (cell_m * cell_m) - 1e-9));
  std::vector<std::int64_t> area(n + 1, 0);
  for (int v : in.labels.data) ++area[v];
  const std::vector<double> med = fragments_medians(in, heights.top);
  const std::vector<double> med_bottom = fragments_medians(in, heights.bottom);
  const auto near = fragments_near_pairs(in, gap);
  std::vector<int> parent(n + 1);
  for (int i = 0; i <= n; ++i) parent[i] = i;
  std::vector<std::int64_t> set_area = area;
  // 1. Pieces a gap apart whose tops agree within the height step are one piece of furniture
  //    (a shadow or a missed row of samples cut it). Touching pieces were split by the height
  //    rule on purpose and are not joined again here (their tops differ).
  for (const auto& [pair, count] : near) {
    const double ta = med[pair.first], tb = med[pair.second];
    if (std::isnan(ta) || std::isnan(tb)) continue;
    if (std::abs(ta - tb) > params.split_height_step_m + 1e-6) continue;
    if (count < kMinContactPairs && area[pair.first] >= min_cells && area[pair.second] >= min_cells)
      continue;
    int a = fragments_find(parent, pair.first), b = fragments_find(parent, pair.second);
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    parent[b] = a;
    set_area[a] += set_area[b];
  }
  // 1b. A piece whose body starts above the floor cannot stand by itself; when its bottom lies
  //     within the height range of a piece a gap away or touching, it rests on that piece: one
  //     object (a chair's backrest on its seat, which the height rule cut off). A table beside a
  //     chair's seat does not rest on it (the table's underside is above the seat), nor does a
  //     cabinet beside a desk (it stands on the floor). Per piece, as in step 1: the medians of
  //     the pieces, not of the sets joined so far.
  for (const auto& [pair, count] : near) {
    int hi = pair.first, lo = pair.second;
    if (std::isnan(med[hi]) || std::isnan(med[lo])) continue;
    if (med[hi] < med[lo]) std::swap(hi, lo);
    const double b_hi = med_bottom[hi], b_lo = med_bottom[lo];
    const double tol = heights.layer_m + 1e-6;
    if (std::isnan(b_hi) || std::isnan(b_lo)) continue;
    if (area[hi] < min_cells || area[lo] < min_cells) continue;    // specks: step 2
    if (count < kMinContactPairs) continue;                        // a corner: two pieces
    if (b_hi - heights.floor_z_m < kRestMinClearance_m) continue;  // stands on the floor
    if (b_hi < b_lo - tol || b_hi > med[lo] + tol) continue;       // not on the lower piece
    int a = fragments_find(parent, hi), b = fragments_find(parent, lo);
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    parent[b] = a;
    set_area[a] += set_area[b];
  }
  // 2. Sets still below the minimum area join the largest set within the gap, whatever its
  //    height (a sliver seen under a table's edge, the lower shelf beside a cabinet); smallest
  //    first. Sets with no such neighbour stay: the caller leaves them over.
  std::vector<int> order;
  for (int i = 1; i <= n; ++i)
    if (fragments_find(parent, i) == i) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return set_area[a] < set_area[b] || (set_area[a] == set_area[b] && a < b);
  });
  for (int piece : order) {
    const int root = fragments_find(parent, piece);
    if (set_area[root] >= min_cells) continue;
    int best = -1;
    for (const auto& [pair, count] : near) {
      const int a = fragments_find(parent, pair.first), b = fragments_find(parent, pair.second);
      if (a == b || (a != root && b != root)) continue;
      const int other = a == root ? b : a;
      if (best < 0 || set_area[other] > set_area[best] ||
          (set_area[other] == set_area[best] && other < best))
        best = other;
    }
    if (best < 0) continue;
    parent[root] = best;
    set_area[best] += set_area[root];
  }
  // Relabel densely in raster order of each set's first cell.
  Labels out;
  out.labels = Grid<std::int32_t>(in.labels.width, in.labels.height, 0);
  std::vector<int> dense(n + 1, 0);
  for (std::size_t i = 0; i < in.labels.size(); ++i) {
    const int v = in.labels.data[i];
    if (!v) continue;
    const int root = fragments_find(parent, v);
    if (!dense[root]) dense[root] = ++out.count;
    out.labels.data[i] = dense[root];
  }
  return out;
}

}  // namespace indoormap::objects::detail
