#include "terrain/HeightField.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>

namespace firmament {

HeightField::HeightField(std::vector<float> heights, int size, double spacing) : size_(size), spacing_(spacing) {
    if (size < 2 || (size & (size - 1)) != 0) throw Error("height field: the size " + std::to_string(size) + " is not a power of two");
    if (heights.size() != static_cast<size_t>(size) * static_cast<size_t>(size))
        throw Error("height field: " + std::to_string(heights.size()) + " heights for " + std::to_string(size) + " x " + std::to_string(size));
    if (!(spacing > 0.0)) throw Error("height field: the sample spacing must be positive");
    const auto [low, high] = std::minmax_element(heights.begin(), heights.end());
    minHeight_ = *low;
    maxHeight_ = *high;
    mips_.push_back(std::move(heights));
    for (int n = size / 2; n >= 1; n /= 2) {
        const std::vector<float>& finer = mips_.back();
        std::vector<float> coarser(static_cast<size_t>(n) * static_cast<size_t>(n));
        const size_t fineSize = static_cast<size_t>(n) * 2;
        for (size_t j = 0; j < static_cast<size_t>(n); ++j)
            for (size_t i = 0; i < static_cast<size_t>(n); ++i) {
                const double sum = static_cast<double>(finer[2 * j * fineSize + 2 * i]) + finer[2 * j * fineSize + 2 * i + 1] +
                                   finer[(2 * j + 1) * fineSize + 2 * i] + finer[(2 * j + 1) * fineSize + 2 * i + 1];
                coarser[j * static_cast<size_t>(n) + i] = static_cast<float>(sum * 0.25);
            }
        mips_.push_back(std::move(coarser));
    }
}

float HeightField::texel(int mip, int i, int j) const {
    const int n = size(mip);
    i = ((i % n) + n) % n;
    j = ((j % n) + n) % n;
    return mips_[static_cast<size_t>(mip)][static_cast<size_t>(j) * static_cast<size_t>(n) + static_cast<size_t>(i)];
}

std::vector<glm::vec2> HeightField::slopes(int mip) const {
    const int n = size(mip);
    const double twoSpacing = 2.0 * spacing_ * static_cast<double>(1 << mip);
    std::vector<glm::vec2> out(static_cast<size_t>(n) * static_cast<size_t>(n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            out[static_cast<size_t>(j) * static_cast<size_t>(n) + static_cast<size_t>(i)] =
                glm::vec2(static_cast<float>((texel(mip, i + 1, j) - texel(mip, i - 1, j)) / twoSpacing),
                          static_cast<float>((texel(mip, i, j + 1) - texel(mip, i, j - 1)) / twoSpacing));
    return out;
}

std::vector<std::vector<float>> HeightField::slopeSecondMoments() const {
    std::vector<std::vector<float>> moments;
    std::vector<float> finest;
    finest.reserve(static_cast<size_t>(size_) * static_cast<size_t>(size_));
    for (const glm::vec2& s : slopes(0)) finest.push_back(static_cast<float>(static_cast<double>(s.x) * s.x + static_cast<double>(s.y) * s.y));
    moments.push_back(std::move(finest));
    for (int n = size_ / 2; n >= 1; n /= 2) {
        const std::vector<float>& finer = moments.back();
        const size_t fineSize = static_cast<size_t>(n) * 2;
        std::vector<float> coarser(static_cast<size_t>(n) * static_cast<size_t>(n));
        for (size_t j = 0; j < static_cast<size_t>(n); ++j)
            for (size_t i = 0; i < static_cast<size_t>(n); ++i)
                coarser[j * static_cast<size_t>(n) + i] =
                    static_cast<float>(0.25 * (static_cast<double>(finer[2 * j * fineSize + 2 * i]) + finer[2 * j * fineSize + 2 * i + 1] +
                                               finer[(2 * j + 1) * fineSize + 2 * i] + finer[(2 * j + 1) * fineSize + 2 * i + 1]));
        moments.push_back(std::move(coarser));
    }
    return moments;
}

double HeightField::sample(double x, double z, int mip) const {
    // Texel k of mip m is centred on x = (2^m k + (2^m - 1) / 2) * spacing.
    const double scale = static_cast<double>(1 << mip);
    const double tx = (x / spacing_ + 0.5) / scale - 0.5, tz = (z / spacing_ + 0.5) / scale - 0.5;
    const double fx = std::floor(tx), fz = std::floor(tz);
    const int i = static_cast<int>(fx), j = static_cast<int>(fz);
    const double wx = tx - fx, wz = tz - fz;
    const double top = texel(mip, i, j) * (1.0 - wx) + texel(mip, i + 1, j) * wx;
    const double bottom = texel(mip, i, j + 1) * (1.0 - wx) + texel(mip, i + 1, j + 1) * wx;
    return top * (1.0 - wz) + bottom * wz;
}

}  // namespace firmament
