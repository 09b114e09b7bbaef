// Fuzz target: --set section.key=value assignments (applyAssignments), one per line of the input.
#include "FuzzSupport.h"

#include "settings/State.h"

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace firmament;
    std::vector<std::string> assignments;
    std::istringstream lines(fuzz::textOf(data, size));
    for (std::string line; std::getline(lines, line);) assignments.push_back(line);
    fuzz::expectOnlyErrors([&] {
        State state;
        applyAssignments(state, assignments);
        // What was assigned is a valid state: it saves and reads back the same.
        const nlohmann::json written = stateToJson(state);
        State again;
        stateFromJson(again, written);
        FUZZ_CHECK(stateToJson(again) == written);
    });
    return 0;
}
