#pragma once
// Conversions between Python objects and the library's values for the `indoormap` module.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/cloud.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/core/polygon.hpp"

namespace indoormap::python {

namespace py = pybind11;

/// A params dict as the YAML tree a config file would give: dict -> mapping (str keys), list /
/// tuple -> sequence, None -> null, bool / int / float / str (and numpy scalars) -> scalars.
/// `where` names the key in errors. Throws InputError("params", ...) for any other value or a
/// nesting deeper than 64 levels (a list holding itself).
YAML::Node yaml_of(const py::handle& value, const std::string& where = "", int depth = 0);

/// A JSON value as Python dicts, lists and numbers (through the json module).
py::object py_of(const nlohmann::json& value);

/// The cells of a grid as an (height, width) uint8 array of indoormap::Cell values; row 0 is
/// the row of the grid origin (the map's lowest y).
py::array_t<std::uint8_t> cells_array(const Grid<Cell>& grid);

/// A navigation map as an (height, width) int8 array in nav_msgs/OccupancyGrid's convention:
/// -1 unknown, 0 free, 100 occupied; row 0 at the origin, as OccupancyGrid.data.
py::array_t<std::int8_t> occupancy_array(const Grid<Cell>& grid);

/// {"origin_m": (x, y), "cell_m", "width", "height"}.
py::dict geometry_dict(const GridGeometry& geometry);

/// An (N, 2) float64 array of a polygon's vertices (map metres, no closing vertex).
py::array_t<double> polygon_array(const Polygon& polygon);

/// An (N, 3) float32 array of points and back. The way in refuses arrays of another shape
/// (ValueError naming `name`) and drops non-finite points, counting them in *dropped.
py::array_t<float> points_array(const std::vector<Eigen::Vector3f>& points);
std::vector<Eigen::Vector3f> points_of(const py::handle& array, const std::string& name,
                                       std::uint64_t* dropped);

/// An (N, 3) float64 array of positions (scanners).
py::array_t<double> positions_array(const std::vector<Eigen::Vector3d>& positions);

}  // namespace indoormap::python
