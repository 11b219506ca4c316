#pragma once
// Writing JSON outputs (private to im_formats): the small value conversions every writer shares.
#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "indoormap/core/polygon.hpp"

namespace indoormap::formats::detail {

/// A point as the JSON array [x, y] (GeoJSON position order), in whatever frame p is in.
template <class Json = nlohmann::json>
Json xy_json(const Eigen::Vector2d& p) {
  return Json::array({p.x(), p.y()});
}

/// A polygon as a GeoJSON linear ring: its vertices, then the first one again.
template <class Json = nlohmann::json>
Json ring_json(const Polygon& poly) {
  Json ring = Json::array();
  for (const auto& v : poly) ring.push_back(xy_json<Json>(v));
  if (!poly.empty()) ring.push_back(xy_json<Json>(poly.front()));
  return ring;
}

}  // namespace indoormap::formats::detail
