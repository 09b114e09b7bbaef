#pragma once
// The terrain's height field and its mip chain on the CPU: what the GPU textures hold, and the
// CPU twin of the shaders' sampling (shaders/terrain/surface.hlsli), for the camera's ground
// clearance and the tests. Sample (i, j) of mip 0 stands at x = i * spacing, z = j * spacing;
// the field repeats every size * spacing metres in x and z.
#include <glm/vec2.hpp>

#include <vector>

namespace firmament {

class HeightField {
public:
    // `heights`: size x size, row-major (rows along z), size a power of two.
    HeightField(std::vector<float> heights, int size, double spacing);  // throws Error for a bad size

    int size(int mip = 0) const { return size_ >> mip; }
    int mipCount() const { return static_cast<int>(mips_.size()); }
    double spacing() const { return spacing_; }
    double tileLength() const { return spacing_ * size_; }
    float minHeight() const { return minHeight_; }
    float maxHeight() const { return maxHeight_; }

    // Mip m: the 2^m x 2^m box average of mip 0, row-major.
    const std::vector<float>& heights(int mip) const { return mips_[static_cast<size_t>(mip)]; }
    // Mip m's slopes (dh/dx, dh/dz) by central differences, row-major.
    std::vector<glm::vec2> slopes(int mip) const;

    // The slopes' second moment E[|s|^2] over each mip's texels: mip 0 holds |s|^2 of mip 0's
    // slopes, each coarser mip the 2 x 2 box average of the finer one. Filtered linearly like any
    // texture, it gives the mean of |s|^2 over a pixel's footprint, so that the variance of the
    // slopes a pixel covers is E[|s|^2] - |E[s]|^2 (LEAN mapping's moments, Olano and Baker 2010).
    std::vector<std::vector<float>> slopeSecondMoments() const;

    // Bilinear between the texel centres of mip `mip`, wrapping: the shaders' heightAt().
    double sample(double x, double z, int mip) const;

private:
    float texel(int mip, int i, int j) const;  // wraps i and j

    int size_;
    double spacing_;
    std::vector<std::vector<float>> mips_;
    float minHeight_ = 0.0f, maxHeight_ = 0.0f;
};

}  // namespace firmament
