// XYZ text, through load_cloud: the same bytes as .xyz and as .csv (which may have a header).
#include "cloud_check.hpp"

INDOORMAP_FUZZ_TARGET(xyz) {
  using namespace indoormap::fuzz;
  const auto dir = fresh_dir();
  for (const char* name : {"cloud.xyz", "cloud.csv"}) {
    try {
      load_and_check(write_file(dir, name, bytes).string());
    } catch (const indoormap::Error&) {
    }
  }
}
