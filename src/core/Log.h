#pragma once
// Plain log lines on stderr: "[firmament] message" / "[firmament] warning: message".
// Stateless, so any part of the program may log without owning anything.
#include <string_view>

namespace firmament::log {

void info(std::string_view message);
void warning(std::string_view message);
void error(std::string_view message);

}  // namespace firmament::log
