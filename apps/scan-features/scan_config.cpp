#include "scan_config.hpp"

#include <cmath>

#include "config_reader.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::app {

void merge_scan_features_config_file(ScanFeaturesConfig& config, const std::string& path) {
  read_config_file(path, [&](auto&& f) { visit_scan_features(config, f); });
}

void validate(const ScanFeaturesConfig& c) {
  c.features.validate();
  c.icp.validate();
  c.search.validate();
  c.log.validate();
  if (!(c.moved_m >= 0.0 && std::isfinite(c.moved_m)))
    throw UsageError("align.moved_m must be >= 0");
  if (!(c.moved_rad >= 0.0 && std::isfinite(c.moved_rad)))
    throw UsageError("align.moved_rad must be >= 0");
  if (c.progress_every_scans < 0)
    throw UsageError("log.progress_every_scans must be >= 0 (0: no progress lines)");
}

std::string to_yaml(const ScanFeaturesConfig& config) {
  ScanFeaturesConfig c = config;
  return config_to_yaml([&](auto&& f) { visit_scan_features(c, f); });
}

nlohmann::json to_json(const ScanFeaturesConfig& config) {
  ScanFeaturesConfig c = config;
  return config_to_json([&](auto&& f) { visit_scan_features(c, f); });
}

}  // namespace indoormap::app
