// The Python module `indoormap` (docs/python.md): a thin front end like the apps. Parameters go
// through the apps' config reader (apps/common/config.hpp), the work through the pipeline of
// pcd-to-map (apps/common/pipeline_run.hpp, apps/pcd-to-map/storey_work.hpp); this file only
// converts between Python and those.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <new>
#include <optional>
#include <string>
#include <vector>

#include "config.hpp"
#include "convert.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/objects_json.hpp"
#include "indoormap/formats/rooms_json.hpp"
#include "indoormap/version.hpp"
#include "pipeline_run.hpp"
#include "storey_work.hpp"

namespace py = pybind11;
using namespace indoormap;
using namespace indoormap::python;

namespace {

// The params dict over the defaults, read and validated as a config file would be.
app::PipelineConfig config_of(const py::object& params) {
  app::PipelineConfig c;
  if (!params.is_none()) {
    if (!py::isinstance<py::dict>(params))
      throw InputError("params", "expected a dict of sections, as config/default.yaml");
    app::merge_config_tree(c, yaml_of(params), "params");
  }
  app::validate(c);
  return c;
}

// A path, an os.PathLike or a list of them.
std::vector<std::string> paths_of(const py::object& cloud) {
  std::vector<std::string> paths;
  const auto one = [&](const py::handle& p) {
    paths.push_back(py::str(py::module_::import("os").attr("fspath")(p)));
  };
  if (py::isinstance<py::list>(cloud) || py::isinstance<py::tuple>(cloud))
    for (const auto& p : cloud) one(p);
  else
    one(cloud);
  return paths;
}

// LAS: the offset subtracted on reading (source units); None for the other formats.
py::object offset_of(const std::optional<Eigen::Vector3d>& offset) {
  if (!offset) return py::none();
  return py::make_tuple(offset->x(), offset->y(), offset->z());
}

py::list inputs_list(const std::vector<cloud_io::InputReport>& inputs) {
  py::list out;
  for (const auto& in : inputs) {
    py::dict d;
    d["path"] = in.path;
    d["format"] = in.format;
    d["points_read"] = in.points_read;
    d["points_dropped"] = in.points_dropped;
    d["scans"] = in.scans;
    d["scanner_known"] = in.scanner_known;
    d["source_offset"] = offset_of(in.source_offset);
    py::list warnings;
    for (const auto& w : in.warnings) warnings.append(w);
    d["warnings"] = warnings;
    out.append(d);
  }
  return out;
}

py::dict load_cloud(const py::object& path, const py::object& params) {
  const app::PipelineConfig cfg = config_of(params);
  const auto paths = paths_of(path);
  cloud_io::LoadResult r;
  {
    py::gil_scoped_release free;
    r = cloud_io::load_clouds(paths, cfg.load);
  }
  py::dict d;
  d["points"] = points_array(r.cloud.points);
  d["scanners"] = positions_array(r.cloud.scanners);
  d["frame"] = "input frame after unit / axis conversion: metres, z up";
  d["format"] = r.inputs.size() == 1 ? r.inputs[0].format : std::string("merged");
  d["inputs"] = inputs_list(r.inputs);
  d["source_offset"] = offset_of(r.source_offset);
  return d;
}

// One storey's results: grids, objects, room border and rooms (map frame, metres).
py::dict storey_dict(app::PipelineRun& run, app::StoreyWork& w, const app::PipelineConfig& cfg) {
  run.map = std::move(w.map);
  const auto& m = run.map;
  py::dict d;
  d["storey"] = w.index;
  d["geometry"] = geometry_dict(m.geometry);
  d["layout"] = cells_array(m.layout.layout);
  d["map"] = occupancy_array(m.nav.map);
  nlohmann::json objs = formats::objects_json(w.objs, m.geometry);
  for (std::size_t k = 0; k < w.objs.objects.size() && k < w.rooms.object_rooms.size(); ++k)
    objs["objects"][k]["room_id"] = w.rooms.object_rooms[k];
  d["objects"] = py_of(objs["objects"]);
  py::dict room;
  room["closed"] = w.border.closed;
  room["polygon_m"] = polygon_array(w.border.polygon_m);
  room["area_m2"] = w.border.area_m2;
  room["perimeter_m"] = w.border.perimeter_m;
  room["reason"] = w.border.reason;
  d["room"] = room;
  std::vector<int> ids;
  for (const auto& o : w.objs.objects) ids.push_back(o.id);
  const auto graph = formats::rooms_graph_json(w.rooms.rooms, ids, w.rooms.object_rooms);
  py::list rooms = py_of(graph["rooms"]);
  for (std::size_t k = 0; k < rooms.size() && k < w.rooms.rooms.rooms.size(); ++k)
    rooms[k]["polygon_m"] = polygon_array(w.rooms.rooms.rooms[k].polygon_m);
  d["rooms"] = rooms;
  d["doors"] = py_of(graph["doors"]);
  d["scanners_m"] = positions_array(m.cloud_map.scanners);
  const auto summary = app::summary_json("python", run, cfg);
  d["warnings"] = py_of(summary["warnings"]);
  d["summary"] = py_of(summary);
  return d;
}

py::dict run_pipeline(const py::object& cloud, const py::object& params, int storey, bool quiet) {
  app::PipelineConfig cfg = config_of(params);
  app::PipelineCli cli;
  cli.storey = storey;
  cli.quiet = quiet;
  app::PipelineRun run;
  std::vector<app::StoreyWork> work;
  if (py::isinstance<py::array>(cloud)) {
    cloud_io::LoadResult loaded;
    cloud_io::InputReport in;
    in.path = "<numpy array>";
    in.format = "numpy";
    loaded.cloud.points = points_of(cloud, in.path, &in.points_dropped);
    in.points_read = loaded.cloud.points.size() + in.points_dropped;
    if (in.points_read > cfg.load.max_points)
      throw BudgetError(in.path + ": " + std::to_string(in.points_read) +
                        " points exceed input.max_points = " + std::to_string(cfg.load.max_points));
    if (loaded.cloud.points.empty()) throw InputError(in.path, "no finite point");
    for (const auto& p : loaded.cloud.points) {  // as load_clouds takes them
      loaded.lo_m = loaded.lo_m.cwiseMin(p);
      loaded.hi_m = loaded.hi_m.cwiseMax(p);
    }
    loaded.inputs.push_back(in);
    cli.inputs = {in.path};
    py::gil_scoped_release free;
    run = app::map_loaded(std::move(loaded), cli, cfg, false, 0.0);
  } else {
    cli.inputs = paths_of(cloud);
    py::gil_scoped_release free;
    run = app::run_pipeline(cli, cfg, false);
  }
  {
    py::gil_scoped_release free;
    for (std::size_t i = 0; i < run.mapped.size(); ++i)
      work.push_back(app::compute_storey(
          run.mapped[i], i == 0 ? std::move(run.map) : std::move(run.more_maps[i - 1]), cfg));
  }
  py::dict first = storey_dict(run, work.front(), cfg);
  py::list more;
  for (std::size_t i = 1; i < work.size(); ++i) more.append(storey_dict(run, work[i], cfg));
  first["more_storeys"] = more;
  first["storeys"] = py_of(app::storeys_json(run));
  return first;
}

}  // namespace

PYBIND11_MODULE(indoormap, m) {
  m.doc() =
      "indoormap: indoor lidar scans -> room layout, navigation map, objects, room polygon "
      "(docs/python.md)";
  m.attr("__version__") = kVersion;
  py::dict cells;
  for (Cell c : {Cell::kUnknown, Cell::kWall, Cell::kFurniture, Cell::kFree})
    cells[py::str(std::string(to_string(c)))] = static_cast<int>(c);
  m.attr("CELLS") = cells;
  // Bad input or parameters: ValueError naming the file (or "params") and the problem.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const BudgetError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const Error& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });
  m.def(
      "default_params", [] { return py_of(app::to_json(app::PipelineConfig{})); },
      "The default parameters as a params dict (the keys of config/default.yaml).");
  m.def("load_cloud", &load_cloud, py::arg("path"), py::arg("params") = py::none(),
        "Loads a cloud (.pcd, .ply, .xyz, .las, 3DTK directory; a list merges) with the apps' "
        "loader: {'points': (N,3) float32, 'scanners': (K,3), 'format', 'inputs', 'frame', "
        "'source_offset'}.");
  m.def("run_pipeline", &run_pipeline, py::arg("cloud"), py::arg("params") = py::none(),
        py::arg("storey") = -1, py::arg("quiet") = false,
        "Runs pcd-to-map's pipeline on a path, a list of paths or an (N,3) array (metres, z up) "
        "with a params dict (the keys of config/default.yaml); returns the grids, objects, room "
        "polygon and rooms (docs/python.md).");
}
