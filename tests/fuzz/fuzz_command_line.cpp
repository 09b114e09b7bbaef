// Fuzz target: the command line (parseCommandLine), the input's NUL-separated words as arguments.
// It never throws: a bad command line is an error text. A good one has a positive resolution
// and frame count.
#include "FuzzSupport.h"

#include "app/CommandLine.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace firmament;
    std::vector<std::string> arguments(1);
    for (size_t i = 0; i < size; ++i) {
        if (data[i] == 0) arguments.emplace_back();
        else arguments.back().push_back(static_cast<char>(data[i]));
    }
    try {
        const ParsedCommandLine parsed = parseCommandLine(arguments);
        if (parsed.error.empty()) {
            FUZZ_CHECK(parsed.options.width > 0 && parsed.options.height > 0);
            FUZZ_CHECK(parsed.options.frameCount() >= 0);
        }
    } catch (const std::exception& e) {
        fuzz::fail("parseCommandLine threw", e.what());
    }
    return 0;
}
