#pragma once
// JSON for the tests that read what the apps write (summary.json, eval.json, ...).
#include <filesystem>
#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace indoormap::test {

/// The JSON document in file p (throws nlohmann::json::parse_error on a malformed file).
inline nlohmann::json read_json(const std::filesystem::path& p) {
  return nlohmann::json::parse(read_text(p));
}

}  // namespace indoormap::test
