#pragma once
// The exposure the tone mapping applied, as the CPU knows it: what the Tone mapping panel shows.
namespace firmament {

struct ExposureReading {
    bool measured = false;          // auto exposure: a value has come back from the GPU
    float averageLuminance = 0.0f;  // adapted log-average luminance (auto exposure only)
    float exposure = 1.0f;          // radiance to scaled luminance: key / L_avg * 2^EV, or 2^EV
};

}  // namespace firmament
