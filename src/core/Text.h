#pragma once
// UTF-16 (Windows) and UTF-8 (everything else in the program) conversions.
#include <string>
#include <string_view>

namespace firmament {

std::string narrow(std::wstring_view text);
std::wstring widen(std::string_view text);

}  // namespace firmament
