// KHR_debug output (core since 4.3): one callback catches every GL error, so no call needs its
// own check. On in debug builds and in tests, where any error fails the test.
#pragma once

#include <string>

namespace haze::gl {

// Installs the callback on the current context (which must have been created with the debug
// flag for messages to be synchronous). Errors are counted and the first few printed.
void enableDebugOutput(bool printErrors = true);
int debugErrorCount();
std::string lastDebugError();
void resetDebugErrors();

}  // namespace haze::gl
