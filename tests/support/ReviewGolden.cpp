// firmament_review_golden OLD.png NEW.png OUT.png: the review image tools/update-goldens
// writes for each changed golden view, the old image, the new one and their difference
// (x16) side by side, with the PSNR and largest difference printed. A missing OLD (a new view)
// shows as black.
#include "support/ImageComparison.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>

int main(int argc, char** argv) {
    using namespace firmament;
    if (argc != 4) {
        std::fprintf(stderr, "usage: firmament_review_golden OLD.png NEW.png OUT.png\n");
        return 2;
    }
    try {
        const Rgba8Image fresh = readPng(argv[2]);
        Rgba8Image old{fresh.width, fresh.height, std::vector<std::uint8_t>(fresh.pixels.size(), 0)};
        if (std::filesystem::exists(argv[1])) old = readPng(argv[1]);
        if (old.width != fresh.width || old.height != fresh.height) {
            std::fprintf(stderr, "%s and %s differ in size: %dx%d and %dx%d\n", argv[1], argv[2], old.width, old.height, fresh.width,
                         fresh.height);
            old = Rgba8Image{fresh.width, fresh.height, std::vector<std::uint8_t>(fresh.pixels.size(), 0)};
        }
        const test::golden::Comparison c = test::golden::compare(old, fresh);
        std::printf("%s: PSNR %.2f dB, largest difference %d at (%d, %d), %zu pixels differ\n", argv[2], c.psnrDb, c.maxDifference,
                    c.worstPixel.x, c.worstPixel.y, c.differingPixels);
        const Rgba8Image difference = test::golden::differenceImage(old, fresh);
        constexpr int kGap = 4;
        Rgba8Image out{fresh.width * 3 + kGap * 2, fresh.height, {}};
        out.pixels.assign(static_cast<size_t>(out.width) * out.height * 4, 255);
        const Rgba8Image* parts[3] = {&old, &fresh, &difference};
        for (int part = 0; part < 3; ++part)
            for (int y = 0; y < fresh.height; ++y)
                std::copy_n(parts[part]->pixel(0, y), fresh.width * 4,
                            out.pixels.begin() + (static_cast<std::ptrdiff_t>(y) * out.width + part * (fresh.width + kGap)) * 4);
        writePng(argv[3], out);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "firmament_review_golden: %s\n", e.what());
        return 1;
    }
}
