#pragma once
// Writing JSON outputs (private to im_formats): the small value conversions every writer shares.
#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace indoormap::formats::detail {

/// A point as the JSON array [x, y] (GeoJSON position order), in whatever frame p is in.
template <class Json = nlohmann::json>
Json xy_json(const Eigen::Vector2d& p) {
  return Json::array({p.x(), p.y()});
}

}  // namespace indoormap::formats::detail
