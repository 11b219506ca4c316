#include "indoormap/core/errors.hpp"

#include <sstream>

namespace indoormap {

namespace {
std::string input_message(const std::string& file, const std::string& problem, std::size_t line) {
  // Built with a stream: GCC 12 warns (-Wrestrict, a false positive) on string concatenation here.
  std::ostringstream msg;
  msg << (file.empty() ? std::string("<input>") : file);
  if (line > 0) msg << ':' << line;
  msg << ": " << problem;
  return msg.str();
}
}  // namespace

InputError::InputError(const std::string& file, const std::string& problem, std::size_t line)
    : Error(input_message(file, problem, line), ExitCode::kBadInput),
      file_(file),
      problem_(problem),
      line_(line) {}

}  // namespace indoormap
