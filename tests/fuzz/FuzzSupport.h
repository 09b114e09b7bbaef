#pragma once
// What every fuzz target holds a parser to: bad input is answered by firmament::Error (or
// SettingsError) naming the problem, never by another exception, a crash, a sanitizer report or
// an answer outside the documented range. Anything else aborts, and libFuzzer keeps the input.
#include "core/Error.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <span>
#include <string>
#include <typeinfo>

namespace firmament::fuzz {

[[noreturn]] inline void fail(const char* what, const char* detail = "") {
    std::fprintf(stderr, "fuzz: %s %s\n", what, detail);
    std::abort();
}

// Runs `parse`; a firmament::Error is an answer, any other exception is a finding.
template <typename Parse>
void expectOnlyErrors(Parse&& parse) {
    try {
        parse();
    } catch (const Error&) {
    } catch (const std::exception& e) {
        fail(typeid(e).name(), e.what());
    } catch (...) {
        fail("an exception that is not a std::exception");
    }
}

inline std::span<const std::uint8_t> bytesOf(const std::uint8_t* data, size_t size) { return {data, size}; }
inline std::string textOf(const std::uint8_t* data, size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }

}  // namespace firmament::fuzz

#define FUZZ_CHECK(condition) \
    do {                                             \
        if (!(condition)) ::firmament::fuzz::fail("check failed:", #condition); \
    } while (false)
