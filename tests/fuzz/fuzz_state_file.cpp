// Fuzz target: the state file (F5/F9, --state-file; --settings reads the same format), with its
// format number and bookmarks. A file that loads saves and loads again to the same state.
#include "FuzzSupport.h"

#include "settings/State.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace firmament;
    fuzz::expectOnlyErrors([&] {
        State state;
        parseStateFile(state, fuzz::bytesOf(data, size), "state.json");
        const nlohmann::json written = stateToJson(state);
        State again;
        stateFromJson(again, written);
        FUZZ_CHECK(stateToJson(again) == written);
    });
    return 0;
}
