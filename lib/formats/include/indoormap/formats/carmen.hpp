#pragma once
// Streaming reader of CARMEN 2D laser logs, plain text or gzip (read directly with zlib).
//
// Messages: `FLASER n r1 .. rn x y theta odom_x odom_y odom_theta ipc_timestamp ipc_hostname
// logger_timestamp` gives a scan (ranges in metres; the pose is the robot's, map frame, metres /
// radians). `PARAM name value ...` sets the laser offset (robot_frontlaser_offset,
// robot_frontlaser_side_offset, robot_frontlaser_angular_offset) and the maximum range
// (robot_front_laser_max) for the scans that follow. Comments (#), empty lines, ODOM, NEFF and
// every other message are skipped. Beam i points at -fov/2 + i * fov / (n - 1) for odd n (both
// ends included, 361 beams over 180 degrees), -fov/2 + i * fov / n for even n (180, 360).
//
// Every bad line (truncated, a beam count that does not match, a non-number, a line longer than
// max_line_bytes, a gzip stream that ends early) throws indoormap::InputError naming the file and
// the 1-based line. Memory is bounded by max_line_bytes and max_beams, whatever the file size.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace indoormap::formats {

struct CarmenReadOptions {
  double fov_rad = 3.14159265358979323846;  ///< the beams span this, centred on the heading
  double default_max_range_m = 81.9;        ///< until a PARAM robot_front_laser_max says otherwise
  std::size_t max_line_bytes = 1 << 16;
  int max_beams = 4096;
  void validate() const;  ///< throws UsageError naming the field
};

/// The laser mounting in the robot frame (x forward, y left), from PARAM lines.
struct CarmenLaserOffset {
  double x_m = 0.0;
  double y_m = 0.0;
  double theta_rad = 0.0;
};

/// One FLASER message.
struct CarmenScan {
  std::vector<float> ranges_m;
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double max_range_m = 0.0;
  double x_m = 0.0, y_m = 0.0, theta_rad = 0.0;  ///< robot pose (corrected logs: SLAM pose)
  double odom_x_m = 0.0, odom_y_m = 0.0, odom_theta_rad = 0.0;
  double ipc_timestamp_s = 0.0;
  double logger_timestamp_s = 0.0;
  CarmenLaserOffset laser_offset;
  std::size_t line = 0;  ///< 1-based line of the message
};

/// Counts of what a reader has seen so far.
struct CarmenStats {
  std::size_t lines = 0;
  std::size_t scans = 0;    ///< FLASER
  std::size_t params = 0;   ///< PARAM (all, used or not)
  std::size_t skipped = 0;  ///< ODOM, NEFF, comments, empty and other messages
};

/// Pull reader: `while (reader.next(scan)) ...`. Not copyable; closes the file on destruction.
class CarmenReader {
 public:
  explicit CarmenReader(const std::string& path, CarmenReadOptions options = {});
  ~CarmenReader();
  CarmenReader(const CarmenReader&) = delete;
  CarmenReader& operator=(const CarmenReader&) = delete;

  /// Reads up to the next FLASER message into out (its buffers are reused); false at the end of
  /// the file. Throws InputError on a bad line.
  bool next(CarmenScan& out);
  const CarmenStats& stats() const { return stats_; }
  const CarmenLaserOffset& laser_offset() const { return offset_; }
  const std::string& path() const { return path_; }

 private:
  struct File;
  bool read_line();
  [[noreturn]] void fail(const std::string& problem) const;
  void parse_param();
  void parse_flaser(CarmenScan& out);

  std::string path_;
  CarmenReadOptions options_;
  std::unique_ptr<File> file_;
  std::vector<char> buffer_;
  std::string_view line_;
  std::vector<std::string_view> tokens_;
  CarmenStats stats_;
  CarmenLaserOffset offset_;
  double max_range_m_ = 0.0;
};

/// Calls on_scan for every FLASER message of the log, in order; returns the counts.
CarmenStats read_carmen(const std::string& path,
                        const std::function<void(const CarmenScan&)>& on_scan,
                        const CarmenReadOptions& options = {});

}  // namespace indoormap::formats
