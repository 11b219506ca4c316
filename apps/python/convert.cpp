#include "convert.hpp"

#include <cmath>
#include <cstring>
#include <sstream>

#include "indoormap/core/errors.hpp"

namespace indoormap::python {

namespace {

constexpr int kMaxParamsDepth = 64;

[[noreturn]] void params_error(const std::string& where, const std::string& problem) {
  throw InputError("params", (where.empty() ? "" : "key '" + where + "': ") + problem);
}

std::string scalar_text(const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(v)) return py::str(v);
  const double d = v.cast<double>();
  if (std::isnan(d)) return ".nan";
  if (std::isinf(d)) return d > 0 ? ".inf" : "-.inf";
  return py::repr(py::float_(d));  // the shortest text that reads back as d
}

}  // namespace

YAML::Node yaml_of(const py::handle& v, const std::string& where, int depth) {
  if (depth > kMaxParamsDepth)
    params_error(where, "nested deeper than " + std::to_string(kMaxParamsDepth) + " levels");
  if (v.is_none()) return YAML::Node(YAML::NodeType::Null);
  if (py::isinstance<py::str>(v)) return YAML::Node(v.cast<std::string>());
  if (py::isinstance<py::bool_>(v) || py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v))
    return YAML::Node(scalar_text(v));
  if (py::isinstance<py::dict>(v)) {
    YAML::Node n(YAML::NodeType::Map);
    for (const auto& kv : v.cast<py::dict>()) {
      if (!py::isinstance<py::str>(kv.first))
        params_error(where, "keys must be strings, got " + std::string(py::repr(kv.first)));
      const auto key = kv.first.cast<std::string>();
      n[key] = yaml_of(kv.second, where.empty() ? key : where + "." + key, depth + 1);
    }
    return n;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v) || py::isinstance<py::array>(v)) {
    const py::object seq =
        py::isinstance<py::array>(v) ? v.attr("tolist")() : py::reinterpret_borrow<py::object>(v);
    if (!py::isinstance<py::list>(seq) && !py::isinstance<py::tuple>(seq))
      return yaml_of(seq, where, depth + 1);  // a 0-d array: its scalar
    YAML::Node n(YAML::NodeType::Sequence);
    std::size_t i = 0;
    for (const auto& e : seq)
      n.push_back(yaml_of(e, where + "[" + std::to_string(i++) + "]", depth + 1));
    return n;
  }
  if (py::hasattr(v, "item") && py::hasattr(v, "dtype"))  // a numpy scalar
    return yaml_of(v.attr("item")(), where, depth + 1);
  params_error(where, "cannot take a value of type " +
                          std::string(py::str(py::type::handle_of(v).attr("__name__"))));
}

py::object py_of(const nlohmann::json& value) {
  return py::module_::import("json").attr("loads")(value.dump());
}

py::array_t<std::uint8_t> cells_array(const Grid<Cell>& g) {
  py::array_t<std::uint8_t> a({g.height, g.width});
  static_assert(sizeof(Cell) == 1);
  if (!g.data.empty()) std::memcpy(a.mutable_data(), g.data.data(), g.data.size());
  return a;
}

py::array_t<std::int8_t> occupancy_array(const Grid<Cell>& g) {
  py::array_t<std::int8_t> a({g.height, g.width});
  std::int8_t* out = a.mutable_data();
  for (std::size_t i = 0; i < g.data.size(); ++i)
    out[i] = g.data[i] == Cell::kFree      ? 0
             : g.data[i] == Cell::kUnknown ? -1
                                           : 100;  // wall or furniture: occupied
  return a;
}

py::dict geometry_dict(const GridGeometry& g) {
  py::dict d;
  d["origin_m"] = py::make_tuple(g.origin_m().x(), g.origin_m().y());
  d["cell_m"] = g.cell_m();
  d["width"] = g.width();
  d["height"] = g.height();
  return d;
}

py::array_t<double> polygon_array(const Polygon& polygon) {
  py::array_t<double> a({static_cast<py::ssize_t>(polygon.size()), py::ssize_t{2}});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    r(i, 0) = polygon[i].x();
    r(i, 1) = polygon[i].y();
  }
  return a;
}

py::array_t<float> points_array(const std::vector<Eigen::Vector3f>& points) {
  py::array_t<float> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float));
  if (!points.empty())
    std::memcpy(a.mutable_data(), points.data(), points.size() * 3 * sizeof(float));
  return a;
}

std::vector<Eigen::Vector3f> points_of(const py::handle& array, const std::string& name,
                                       std::uint64_t* dropped) {
  py::array_t<float, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  } catch (const py::error_already_set&) {
  }
  if (!a || a.ndim() != 2 || a.shape(1) != 3)
    throw InputError(name, "expected an (N, 3) array of x, y, z in metres");
  const auto r = a.unchecked<2>();
  std::vector<Eigen::Vector3f> points;
  points.reserve(static_cast<std::size_t>(a.shape(0)));
  *dropped = 0;
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    const Eigen::Vector3f p(r(i, 0), r(i, 1), r(i, 2));
    if (p.allFinite())
      points.push_back(p);
    else
      ++*dropped;
  }
  return points;
}

py::array_t<double> positions_array(const std::vector<Eigen::Vector3d>& positions) {
  py::array_t<double> a({static_cast<py::ssize_t>(positions.size()), py::ssize_t{3}});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < positions.size(); ++i)
    for (int k = 0; k < 3; ++k) r(i, k) = positions[i][k];
  return a;
}

}  // namespace indoormap::python
