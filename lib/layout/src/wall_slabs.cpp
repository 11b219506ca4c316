// A wall one of whose faces only the furniture band holds (docs/pipeline.md, "The inside of
// inner walls"): the slab between two observed floors, at most a wall thick.
#include <cmath>

#include "indoormap/layout/layout.hpp"

namespace indoormap::layout {

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

}  // namespace indoormap::layout
