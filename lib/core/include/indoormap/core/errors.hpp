#pragma once
// Typed errors for broken preconditions. Expected outcomes (no ceiling, no route) are data in
// results, never exceptions. Every app catches indoormap::Error in main and maps exit_code().
#include <cstddef>
#include <stdexcept>
#include <string>

namespace indoormap {

/// Exit codes shared by every app.
enum class ExitCode : int { kOk = 0, kFailure = 1, kBadInput = 2, kNoResult = 3 };

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what, ExitCode code = ExitCode::kFailure)
      : std::runtime_error(what), code_(code) {}
  ExitCode exit_code() const { return code_; }

 private:
  ExitCode code_;
};

/// Bad input data: names the file and, where known, the 1-based line.
class InputError : public Error {
 public:
  InputError(const std::string& file, const std::string& problem, std::size_t line = 0);
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  std::string problem_;
  std::size_t line_;
};

/// Bad parameters or command-line usage (names the key or option).
class UsageError : public Error {
 public:
  explicit UsageError(const std::string& what) : Error(what, ExitCode::kBadInput) {}
};

/// A size derived from the input exceeds a configured budget; raised before allocating.
class BudgetError : public Error {
 public:
  explicit BudgetError(const std::string& what) : Error(what, ExitCode::kBadInput) {}
};

/// An output could not be written (unwritable directory, disk full).
class OutputError : public Error {
 public:
  OutputError(const std::string& path, const std::string& problem)
      : Error("cannot write '" + path + "': " + problem, ExitCode::kFailure) {}
};

}  // namespace indoormap
