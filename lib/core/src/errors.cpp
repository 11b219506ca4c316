#include "indoormap/core/errors.hpp"

namespace indoormap {

namespace {
std::string input_message(const std::string& file, const std::string& problem, std::size_t line) {
  std::string where = file.empty() ? std::string("<input>") : file;
  if (line > 0) where += ":" + std::to_string(line);
  return where + ": " + problem;
}
}  // namespace

InputError::InputError(const std::string& file, const std::string& problem, std::size_t line)
    : Error(input_message(file, problem, line), ExitCode::kBadInput), file_(file), line_(line) {}

}  // namespace indoormap
