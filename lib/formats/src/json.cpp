#include "indoormap/formats/json.hpp"

#include "indoormap/core/atomic_file.hpp"

namespace indoormap::formats {

void write_json(const std::filesystem::path& path, const nlohmann::json& j) {
  write_file_atomic(path, j.dump(2) + "\n");
}

void write_json(const std::filesystem::path& path, const nlohmann::ordered_json& j) {
  write_file_atomic(path, j.dump(2) + "\n");
}

}  // namespace indoormap::formats
