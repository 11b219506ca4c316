#include "json_read.hpp"

#include <cmath>
#include <fstream>

#include "indoormap/core/input_file.hpp"

namespace indoormap::formats::detail {

namespace fs = std::filesystem;
using nlohmann::json;

json parse_json_file(const fs::path& path) {
  const std::string bytes = read_input_file(path, kMaxTextInputBytes, "a JSON file");
  json j;
  try {
    j = json::parse(bytes);
  } catch (const json::exception& e) {  // parse errors, and out_of_range for numbers like 1e999
    throw InputError(path.string(), std::string("invalid JSON: ") + e.what());
  }
  if (!j.is_object()) throw InputError(path.string(), "the top level is not a JSON object");
  return j;
}

void bad(const fs::path& path, const std::string& key, const std::string& problem) {
  throw InputError(path.string(), "key '" + key + "': " + problem);
}

double number(const json& j, const fs::path& path, const std::string& key) {
  if (!j.is_number()) bad(path, key, "expected a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) bad(path, key, "not finite");
  return v;
}

Eigen::Vector2d point(const json& j, const fs::path& path, const std::string& key) {
  if (!j.is_array() || j.size() < 2) bad(path, key, "expected [x, y]");
  return {number(j[0], path, key + "[0]"), number(j[1], path, key + "[1]")};
}

Polygon polygon(const json& j, const fs::path& path, const std::string& key) {
  if (!j.is_array()) bad(path, key, "expected a list of [x, y] points");
  if (j.size() > 1'000'000) bad(path, key, "more than 1,000,000 vertices");
  Polygon poly;
  for (std::size_t i = 0; i < j.size(); ++i)
    poly.push_back(point(j[i], path, key + "[" + std::to_string(i) + "]"));
  if (poly.size() >= 2 && (poly.front() - poly.back()).norm() < 1e-12)
    poly.pop_back();  // closed ring
  if (poly.size() < 3) bad(path, key, "a polygon needs at least 3 distinct vertices");
  return poly;
}

const json& member(const json& j, const char* name, const fs::path& path, const std::string& key) {
  if (!j.is_object() || !j.contains(name))
    bad(path, key.empty() ? name : key + "." + name, "missing");
  return j.at(name);
}

}  // namespace indoormap::formats::detail
