// PLY (.ply): ascii, binary_little_endian, binary_big_endian, through load_cloud.
#include "cloud_check.hpp"

INDOORMAP_FUZZ_TARGET(ply) {
  using namespace indoormap::fuzz;
  load_and_check(write_file(fresh_dir(), "cloud.ply", bytes).string());
}
