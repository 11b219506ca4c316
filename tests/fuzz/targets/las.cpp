// LAS (.las) 1.2-1.4, point formats 0-10, header and VLR validation, through load_cloud.
#include "cloud_check.hpp"

INDOORMAP_FUZZ_TARGET(las) {
  using namespace indoormap::fuzz;
  load_and_check(write_file(fresh_dir(), "cloud.las", bytes).string());
}
