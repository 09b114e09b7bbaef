// Fuzz target: settings JSON (core/SettingsJson), the layer every settings file, state file,
// bookmark and flight keyframe goes through. A document that reads must also round-trip: written
// out and read into fresh settings, it gives the same JSON again.
#include "FuzzSupport.h"

#include "core/SettingsJson.h"
#include "settings/State.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
    using namespace firmament;
    const nlohmann::json document = nlohmann::json::parse(data, data + size, nullptr, false);
    if (document.is_discarded()) return 0;  // not JSON: the JSON library's own job
    fuzz::expectOnlyErrors([&] {
        State state;
        settingsFromJson(document, state.sections());
        const nlohmann::json written = settingsToJson(state.sections());
        State again;
        settingsFromJson(written, again.sections());
        FUZZ_CHECK(settingsToJson(again.sections()) == written);
    });
    return 0;
}
