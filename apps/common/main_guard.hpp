#pragma once
// The one main guard of every app: typed errors to the documented exit codes.
#include <functional>
#include <string>

namespace indoormap::app {

/// Runs body, maps exceptions to the documented exit codes (indoormap::Error: its exit_code();
/// std::bad_alloc and any other exception: 1) and prints "<prog>: <message>" on stderr.
/// argv is recorded first as the run's command line and start time (provenance.hpp).
int run_guarded(const std::string& prog, int argc, const char* const* argv,
                const std::function<int()>& body);

}  // namespace indoormap::app
