// Fuzz target: the PNG decoder (golden images, decodePng). A picture that decodes has
// width x height x 4 bytes and encodes and decodes again to the same pixels.
#include "FuzzSupport.h"

#include "core/PngImage.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace firmament;
    fuzz::expectOnlyErrors([&] {
        const Rgba8Image image = decodePng(fuzz::bytesOf(data, size));
        FUZZ_CHECK(image.pixels.size() == static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 4);
        FUZZ_CHECK(decodePng(encodePng(image)).pixels == image.pixels);
    });
    return 0;
}
