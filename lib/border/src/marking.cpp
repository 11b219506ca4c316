// Steps 1-3 of the closure: the heavy border, M_Lee and the border components.
#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "indoormap/core/errors.hpp"
#include "internal.hpp"

namespace indoormap::border {

using namespace detail;

namespace {

cv::Mat as_mat(Grid<std::uint8_t>& g) {
  return cv::Mat(g.height, g.width, CV_8U, g.data.data());
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

Grid<std::uint8_t> heavy_border(const Grid<Cell>& layout, const BorderParams& params) {
  params.validate();
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

}  // namespace indoormap::border
