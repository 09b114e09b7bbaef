#pragma once
// The largest picture the image readers accept: a damaged or hostile header must not make them
// allocate gigabytes (found by fuzzing, docs/reliability.md). 16384 x 16384 is the largest
// --resolution and so the largest capture; every table and height field is far smaller.
#include <cstdint>
#include <string>

namespace firmament {

inline constexpr std::int64_t kMaxImageSide = 16384;
inline constexpr std::int64_t kMaxImagePixels = kMaxImageSide * kMaxImageSide;

// Empty when a width x height picture is within the limits; else why not.
inline std::string checkImageSize(std::int64_t width, std::int64_t height) {
    if (width <= 0 || height <= 0) return "its size " + std::to_string(width) + " x " + std::to_string(height) + " is empty";
    if (width > kMaxImageSide || height > kMaxImageSide)
        return "its size " + std::to_string(width) + " x " + std::to_string(height) + " exceeds " + std::to_string(kMaxImageSide) +
               " pixels a side";
    return {};
}

}  // namespace firmament
