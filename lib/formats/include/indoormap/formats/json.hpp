#pragma once
// JSON files: writing (2-space indent, newline-terminated, atomic).
#include <filesystem>
#include <nlohmann/json.hpp>

namespace indoormap::formats {

/// Writes JSON (2-space indent) atomically.
void write_json(const std::filesystem::path& path, const nlohmann::json& j);
/// The same for a JSON object that keeps its keys in insertion order.
void write_json(const std::filesystem::path& path, const nlohmann::ordered_json& j);

}  // namespace indoormap::formats
