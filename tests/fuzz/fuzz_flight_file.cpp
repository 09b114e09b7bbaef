// Fuzz target: flight files (--flight). A flight that loads is played: every time from before the
// start to past the end gives a view, and captures come in time order.
#include "FuzzSupport.h"

#include "app/FlightPath.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace firmament;
    fuzz::expectOnlyErrors([&] {
        const FlightPath flight = FlightPath::parse(fuzz::bytesOf(data, size), "flight.json");
        FUZZ_CHECK(flight.size() >= 1);
        const double end = flight.duration();
        FUZZ_CHECK(std::isfinite(end) && end >= 0.0);
        for (int i = -1; i <= 9; ++i) (void)flight.at(end * i / 8.0);
        double previous = -1.0;
        for (const FlightCapture& capture : flight.captures()) {
            FUZZ_CHECK(capture.time >= previous);
            previous = capture.time;
        }
        (void)flight.capturesBetween(-1.0, end);
        (void)flight.describe();
    });
    return 0;
}
