#pragma once
// The one main guard of every app: typed errors to the documented exit codes.
#include <functional>
#include <string>

namespace indoormap::app {

/// Runs body, maps exceptions to the documented exit codes (indoormap::Error: its exit_code();
/// std::bad_alloc and any other exception: 1) and prints "<prog>: <message>" on stderr.
int run_guarded(const std::string& prog, const std::function<int()>& body);

}  // namespace indoormap::app
