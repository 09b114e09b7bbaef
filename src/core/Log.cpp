#include "core/Log.h"

#include <cstdio>

namespace firmament::log {

namespace {
void write(std::string_view prefix, std::string_view message) {
    std::fprintf(stderr, "[firmament] %.*s%.*s\n", static_cast<int>(prefix.size()), prefix.data(),
                 static_cast<int>(message.size()), message.data());
    std::fflush(stderr);
}
}  // namespace

void info(std::string_view message) { write("", message); }
void warning(std::string_view message) { write("warning: ", message); }
void error(std::string_view message) { write("error: ", message); }

}  // namespace firmament::log
