#include "main_guard.hpp"

#include <iostream>
#include <new>

#include "indoormap/core/errors.hpp"
#include "provenance.hpp"

namespace indoormap::app {

int run_guarded(const std::string& prog, int argc, const char* const* argv,
                const std::function<int()>& body) {
  record_invocation(argc, argv);
  try {
    return body();
  } catch (const Error& e) {
    std::cerr << prog << ": " << e.what() << "\n";
    return static_cast<int>(e.exit_code());
  } catch (const std::bad_alloc&) {
    std::cerr << prog << ": out of memory\n";
    return static_cast<int>(ExitCode::kFailure);
  } catch (const std::exception& e) {
    std::cerr << prog << ": " << e.what() << "\n";
    return static_cast<int>(ExitCode::kFailure);
  }
}

}  // namespace indoormap::app
