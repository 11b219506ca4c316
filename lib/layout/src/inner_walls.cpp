// The walls between rooms (docs/pipeline.md, "The inside of inner walls" and "A wall with one
// face in the wall band"): a wall's unseen inside between its two faces in M_w, and the slab
// between two observed floors, at most a wall thick, with one face in the wall band only.
#include "inner_walls.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace indoormap::layout {

Grid<std::uint8_t> wall_inside(const Grid<std::uint8_t>& walls, double cell_m, double max_span_m,
                               const Grid<std::uint8_t>* open,
                               const Grid<std::uint8_t>* furniture) {
  const int w = walls.width, h = walls.height;
  if (open && (open->width != w || open->height != h)) open = nullptr;
  if (furniture && (furniture->width != w || furniture->height != h)) furniture = nullptr;
  const int dirs[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};
  Grid<std::uint8_t> out(w, h, 0);
  std::vector<CellIndex> line;
  for (const auto& d : dirs) {
    const int dc = d[0], dr = d[1];
    const double step_m = cell_m * std::hypot(dc, dr);
    const int max_cells = static_cast<int>(std::floor(max_span_m / step_m + 1e-9));
    // Whether open space lies just past the wall piece that ends (or starts) at index i, walking
    // by `dir` (-1 back, +1 on), past the furniture-band face in front of it; a piece longer
    // than a wall is thick is no face.
    const auto open_past = [&](int i, int dir) {
      const int n = static_cast<int>(line.size());
      int k = i, walls_n = 0, furn_n = 0;
      for (; k >= 0 && k < n && walls.at(line[k].col, line[k].row); k += dir) ++walls_n;
      for (; furniture && k >= 0 && k < n && furniture->at(line[k].col, line[k].row); k += dir)
        ++furn_n;
      return walls_n <= max_cells && furn_n <= max_cells && k >= 0 && k < n &&
             open->at(line[k].col, line[k].row);
    };
    // Whether, past that wall piece, a gap no wider than a wall, none of it open, ends at
    // another wall piece: the line crosses a second wall's inside next to this gap.
    const auto wall_gap_past = [&](int i, int dir) {
      const int n = static_cast<int>(line.size());
      int k = i, walls_n = 0, gap = 0;
      for (; k >= 0 && k < n && walls.at(line[k].col, line[k].row); k += dir) ++walls_n;
      for (; k >= 0 && k < n && !walls.at(line[k].col, line[k].row); k += dir, ++gap)
        if (open->at(line[k].col, line[k].row)) return false;
      return walls_n <= max_cells && gap > 0 && (gap + 1) * step_m <= max_span_m + 1e-9 && k >= 0 &&
             k < n;
    };
    // A gap qualifies when open space lies past one of its wall pieces (a wall between two
    // rooms), or when past neither lies a second wall's inside (a wall with furniture on both
    // sides); not when it lies between the faces of a room's corner, each backed by its wall.
    const auto qualifies = [&](int a, int b) {
      return !open || open_past(a, -1) || open_past(b, +1) ||
             (!wall_gap_past(a, -1) && !wall_gap_past(b, +1));
    };
    for (int r0 = 0; r0 < h; ++r0)
      for (int c0 = 0; c0 < w; ++c0) {
        if (walls.contains(c0 - dc, r0 - dr)) continue;  // not the first cell of its line
        line.clear();
        for (int c = c0, r = r0; walls.contains(c, r); c += dc, r += dr) line.push_back({c, r});
        int last_wall = -1;
        for (int i = 0; i < static_cast<int>(line.size()); ++i) {
          if (!walls.at(line[i].col, line[i].row)) continue;
          const int gap = i - last_wall - 1;
          // The gap between two wall pieces: at most max_span_m from wall cell to wall cell;
          // with `open`, the far side of one of the two pieces is open space (a wall's faces
          // look at two rooms; two faces of one room's corner look at each other).
          if (last_wall >= 0 && gap > 0 && (gap + 1) * step_m <= max_span_m + 1e-9 &&
              qualifies(last_wall, i))
            for (int k = last_wall + 1; k < i; ++k) out.at(line[k].col, line[k].row) = 1;
          last_wall = i;
        }
      }
  }
  return out;
}

Grid<std::uint8_t> wall_slabs(const Grid<std::uint8_t>& walls, const Grid<std::uint8_t>& furniture,
                              const Grid<std::uint8_t>& seen, double cell_m, double max_span_m) {
  const int w = walls.width, h = walls.height;
  Grid<std::uint8_t> out(w, h, 0);
  if (furniture.width != w || furniture.height != h || seen.width != w || seen.height != h ||
      max_span_m <= 0)
    return out;
  const int dirs[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};
  for (const auto& d : dirs) {
    const int dc = d[0], dr = d[1];
    const double step_m = cell_m * std::hypot(dc, dr);
    // A run: the unseen cells between two seen ones along the line, at most max_span_m long.
    const int max_run = static_cast<int>(std::floor(max_span_m / step_m + 1e-9));
    for (int r0 = 0; r0 < h; ++r0)
      for (int c0 = 0; c0 < w; ++c0) {
        if (walls.contains(c0 - dc, r0 - dr)) continue;  // not the first cell of its line
        int run_c = -1, run_r = -1, len = 0, first_wall = -1, last_wall = -1, walls_in_run = 0;
        bool after_seen = false, first_furn = false, prev_furn = false;
        for (int c = c0, r = r0; walls.contains(c, r); c += dc, r += dr) {
          if (seen.at(c, r)) {
            // One face in M_w: its wall cells one unbroken piece at one end of the run; the
            // other face in the furniture band only, at the other end.
            const bool wall_first = first_wall == 0, wall_last = last_wall == len - 1;
            const bool one_face = walls_in_run > 0 && last_wall - first_wall + 1 == walls_in_run &&
                                  wall_first != wall_last && (wall_first ? prev_furn : first_furn);
            if (after_seen && len > 0 && len <= max_run && one_face)
              for (int k = 0; k < len; ++k) out.at(run_c + k * dc, run_r + k * dr) = 1;
            after_seen = true;
            len = walls_in_run = 0;
            first_wall = last_wall = -1;
            continue;
          }
          if (len == 0) run_c = c, run_r = r;
          if (walls.at(c, r)) {
            if (first_wall < 0) first_wall = len;
            last_wall = len;
            ++walls_in_run;
          }
          prev_furn = furniture.at(c, r) && !walls.at(c, r);  // the last cell of the run so far
          if (len == 0) first_furn = prev_furn;
          ++len;
        }
      }
  }
  return out;
}

namespace detail {

namespace {

cv::Mat as_mat(Grid<std::uint8_t>& g) {
  return cv::Mat(g.height, g.width, CV_8U, g.data.data());
}

// Adds to `walls` the cells of `cand` inside the passage area, neither flooded nor seen, whose
// 8-connected piece spans more than 2 * max_span_m along an axis. A pillar's inside is left as
// it is: the objects step describes a pillar by its ring of faces; a wall's inside is longer.
void add_long_pieces(const Grid<std::uint8_t>& cand_in, const Grid<std::uint8_t>& passage,
                     const Grid<std::uint8_t>& free_mask, const Grid<std::uint8_t>* seen,
                     double cell_m, double max_span_m, Grid<std::uint8_t>& walls) {
  Grid<std::uint8_t> cand(walls.width, walls.height, 0);
  for (std::size_t i = 0; i < cand.size(); ++i)
    cand.data[i] =
        cand_in.data[i] && passage.data[i] && !free_mask.data[i] && !(seen && seen->data[i]);
  cv::Mat lab, st, cen;
  cv::connectedComponentsWithStats(as_mat(cand), lab, st, cen, 8, CV_32S);
  const int max_cells = static_cast<int>(std::lround(2.0 * max_span_m / cell_m));
  for (int row = 0; row < walls.height; ++row)
    for (int col = 0; col < walls.width; ++col) {
      const int k = lab.at<int>(row, col);
      if (k > 0 &&
          std::max(st.at<int>(k, cv::CC_STAT_WIDTH), st.at<int>(k, cv::CC_STAT_HEIGHT)) > max_cells)
        walls.at(col, row) = 1;
    }
}

}  // namespace

void add_inner_walls(const Grid<std::uint8_t>& furniture, const Grid<std::uint8_t>* seen,
                     const Grid<std::uint8_t>& passage, const Grid<std::uint8_t>& free_mask,
                     double cell_m, double max_span_m, Grid<std::uint8_t>& walls) {
  // The slabs are found before the insides are added: their runs ask for one wall face.
  Grid<std::uint8_t> slabs;
  if (seen) slabs = wall_slabs(walls, furniture, *seen, cell_m, max_span_m);
  Grid<std::uint8_t> open = free_mask;
  if (seen)
    for (std::size_t i = 0; i < open.size(); ++i) open.data[i] |= seen->data[i];
  add_long_pieces(wall_inside(walls, cell_m, max_span_m, &open, &furniture), passage, free_mask,
                  seen, cell_m, max_span_m, walls);
  if (seen) add_long_pieces(slabs, passage, free_mask, seen, cell_m, max_span_m, walls);
}

}  // namespace detail

}  // namespace indoormap::layout
