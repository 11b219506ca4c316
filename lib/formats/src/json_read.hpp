#pragma once
// Reading JSON inputs (private to im_formats): every problem is an InputError naming the file
// and the key.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/polygon.hpp"

namespace indoormap::formats::detail {

/// Parses a JSON file whose top level must be an object.
nlohmann::json parse_json_file(const std::filesystem::path& path);

// Any JSON access the readers did not check by hand (a value of an unexpected type deep in the
// file) becomes an InputError naming the file, never an untyped exception.
template <class F>
auto guarded(const std::filesystem::path& path, F&& read) {
  try {
    return read();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string(), std::string("unexpected JSON content: ") + e.what());
  }
}

[[noreturn]] void bad(const std::filesystem::path& path, const std::string& key,
                      const std::string& problem);
/// A finite number.
double number(const nlohmann::json& j, const std::filesystem::path& path, const std::string& key);
/// [x, y] (further entries ignored).
Eigen::Vector2d point(const nlohmann::json& j, const std::filesystem::path& path,
                      const std::string& key);
/// A list of [x, y] points, at least 3 distinct; a closing repeat of the first is dropped.
Polygon polygon(const nlohmann::json& j, const std::filesystem::path& path, const std::string& key);
/// j[name], which must exist (j must be an object).
const nlohmann::json& member(const nlohmann::json& j, const char* name,
                             const std::filesystem::path& path, const std::string& key);

}  // namespace indoormap::formats::detail
