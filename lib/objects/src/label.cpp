#include "indoormap/objects/label.hpp"

#include <numeric>
#include <vector>

namespace indoormap::objects {

namespace {

// Union-find over provisional marks; the representative is the smallest mark of its set, so the
// backward pass maps every cell to the minimum equivalent mark, as the paper does.
class UnionFind {
 public:
  int make() {
    parent_.push_back(static_cast<int>(parent_.size()));
    return parent_.back();
  }
  int find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) parent_[b] = a;
    else parent_[a] = b;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace

Labels label_components(const Grid<std::uint8_t>& mask, Connectivity connectivity,
                        const std::function<bool(CellIndex, CellIndex)>& joins) {
  const int w = mask.width, h = mask.height;
  Labels out;
  out.labels = Grid<std::int32_t>(w, h, 0);
  if (w == 0 || h == 0) return out;
  UnionFind uf;
  uf.make();  // mark 0 = background
  // Already-visited neighbours of (c, r): left, then the row before (left-up, up, right-up).
  const int n_prev = connectivity == Connectivity::k8 ? 4 : 2;
  const int dc[4] = {-1, 0, -1, 1};
  const int dr[4] = {0, -1, -1, -1};
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      if (!mask.at(c, r)) continue;
      int mark = 0;
      for (int k = 0; k < n_prev; ++k) {
        const int nc = c + dc[k], nr = r + dr[k];
        if (!mask.contains(nc, nr)) continue;
        const int m = out.labels.at(nc, nr);
        if (m == 0 || (joins && !joins({c, r}, {nc, nr}))) continue;
        if (mark == 0) mark = m;
        else if (m != mark) uf.unite(mark, m);
        mark = std::min(mark, m);
      }
      out.labels.at(c, r) = mark ? mark : uf.make();
    }
  // Backward pass: the minimum equivalent mark, renumbered densely in raster order.
  std::vector<int> dense;
  for (auto& v : out.labels.data) {
    if (!v) continue;
    const int root = uf.find(v);
    if (static_cast<std::size_t>(root) >= dense.size()) dense.resize(root + 1, 0);
    if (!dense[root]) dense[root] = ++out.count;
    v = dense[root];
  }
  return out;
}

}  // namespace indoormap::objects
