// Fuzz target: the OpenEXR readers the table cache and captures use (decodeExr, decodeFloatExr,
// decodeFloatChannelExr over OpenEXR), and the cache's header check. A file that decodes has
// as many values as its size says.
#include "FuzzSupport.h"

#include "core/ExrImage.h"
#include "tables/TableFileHeaders.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace firmament;
    const auto bytes = fuzz::bytesOf(data, size);
    fuzz::expectOnlyErrors([&] {
        const FloatExrFile file = decodeFloatExr(bytes, "table.exr");
        FUZZ_CHECK(file.image.rgba.size() == static_cast<size_t>(file.image.width) * static_cast<size_t>(file.image.height) * 4);
        (void)checkTableHeader(file.attributes, "0123456789abcdef", 32, 32, file.image.width, file.image.height);
    });
    fuzz::expectOnlyErrors([&] {
        const FloatImageFile file = decodeFloatChannelExr(bytes, "heights.exr");
        FUZZ_CHECK(file.image.values.size() == static_cast<size_t>(file.image.width) * static_cast<size_t>(file.image.height));
    });
    fuzz::expectOnlyErrors([&] {
        const ExrFile file = decodeExr(bytes, "capture.exr");
        FUZZ_CHECK(file.image.halfBits.size() == static_cast<size_t>(file.image.width) * static_cast<size_t>(file.image.height) * 4);
    });
    return 0;
}
