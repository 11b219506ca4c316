#include "indoormap/core/errors.hpp"

#include <string_view>

namespace indoormap {

namespace {
std::string input_message(const std::string& file, const std::string& problem, std::size_t line) {
  std::string msg;
  msg.reserve(file.size() + problem.size() + 32);
  msg.append(file.empty() ? std::string_view("<input>") : std::string_view(file));
  if (line > 0) msg.append(":").append(std::to_string(line));
  msg.append(": ").append(problem);
  return msg;
}
}  // namespace

InputError::InputError(const std::string& file, const std::string& problem, std::size_t line)
    : Error(input_message(file, problem, line), ExitCode::kBadInput), file_(file), line_(line) {}

}  // namespace indoormap
