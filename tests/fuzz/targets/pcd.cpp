// PCD (.pcd): our header validation, then PCL's reader (binary, binary_compressed) or our own
// strict ascii reader, through load_cloud.
#include "cloud_check.hpp"

INDOORMAP_FUZZ_TARGET(pcd) {
  using namespace indoormap::fuzz;
  load_and_check(write_file(fresh_dir(), "cloud.pcd", bytes).string());
}
