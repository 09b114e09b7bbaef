#pragma once
// Turns a failed HRESULT into an Error naming the call that failed and the code.
#include "core/Error.h"

#include <windows.h>

#include <cstdio>
#include <string>
#include <string_view>

namespace firmament {

inline void check(HRESULT hr, std::string_view what) {
    if (SUCCEEDED(hr)) return;
    char code[16];
    std::snprintf(code, sizeof code, "0x%08lX", static_cast<unsigned long>(hr));
    throw Error(std::string(what) + " failed (HRESULT " + code + ")");
}

}  // namespace firmament
