// The trajectory reader (formats/trajectory.hpp): TUM and plain x y z, and its errors.
#include <gtest/gtest.h>

#include "indoormap/core/errors.hpp"
#include "indoormap/formats/trajectory.hpp"
#include "test_support.hpp"

using namespace indoormap;

namespace {

std::string error_of(const std::string& text) {
  const auto f = test::scratch_dir() / "t.txt";
  test::write_text(f, text);
  try {
    formats::read_trajectory(f);
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ": " + e.problem();
  }
  return "no error";
}

}  // namespace

TEST(Trajectory, ReadsTumAndPlain) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "tum.txt",
                   "# timestamp tx ty tz qx qy qz qw\n"
                   "0.0 1.0 2.0 1.5 0 0 0 1\n\n"
                   "0.5 1.5 2.0 1.5 0 0 0.7071068 0.7071068\n");
  const auto t = formats::read_trajectory(dir / "tum.txt");
  EXPECT_EQ(t.format, formats::TrajectoryFormat::kTum);
  ASSERT_EQ(t.positions.size(), 2u);
  EXPECT_EQ(t.positions[1], Eigen::Vector3d(1.5, 2.0, 1.5));
  EXPECT_EQ(t.lines[1], 4u);
  test::write_text(dir / "plain.txt", "1 2 3\n4,5,6\r\n");
  const auto p = formats::read_trajectory(dir / "plain.txt");
  EXPECT_EQ(p.format, formats::TrajectoryFormat::kPlain);
  ASSERT_EQ(p.positions.size(), 2u);
  EXPECT_EQ(p.positions[1], Eigen::Vector3d(4, 5, 6));
}

TEST(Trajectory, ErrorsNameTheLine) {
  EXPECT_EQ(error_of("0 1 2 3 0 0 0 1\n0 1 x 3 0 0 0 1\n"),
            "2: column 3: 'x' is not a finite number");
  EXPECT_EQ(error_of("1 2 3\n1 2 3 4\n"),
            "2: expected 8 columns 't x y z qx qy qz qw' (TUM) or 3 'x y z', got 4");
  EXPECT_EQ(error_of("1 2 3\n0 1 2 3 0 0 0 1\n"),
            "2: 8 columns where the file's first pose line has 3");
  EXPECT_EQ(error_of("0 1 2 3 0 0 0 1.01\n"),
            "1: quaternion (qx qy qz qw) has norm 1.01, expected 1 within 0.001");
  EXPECT_EQ(error_of("1 2 nan\n"), "1: column 3: 'nan' is not a finite number");
  EXPECT_EQ(error_of("# only a comment\n"), "0: no pose line (empty trajectory)");
  // Within the tolerance: a quaternion rounded to 4 digits passes.
  EXPECT_EQ(error_of("0 1 2 3 0 0 0.7071 0.7071\n"), "no error");
}
