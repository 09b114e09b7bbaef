#include "settings/State.h"

#include "core/FileIO.h"
#include "core/SettingsJson.h"

namespace firmament {

using nlohmann::json;

std::vector<SettingsSection> Bookmark::sections() {
    return {{"camera", [this](SettingsVisitor& v) { camera.visit(v); }}, {"sun", [this](SettingsVisitor& v) { sun.visit(v); }}};
}

std::vector<SettingsSection> State::sections() {
    return {{"display", [this](SettingsVisitor& v) { display.visit(v); }},
            {"scene", [this](SettingsVisitor& v) { scene.visit(v); }},
            {"camera", [this](SettingsVisitor& v) { camera.visit(v); }},
            {"sun", [this](SettingsVisitor& v) { sun.visit(v); }},
            {"flight", [this](SettingsVisitor& v) { flight.visit(v); }},
            {"devices", [this](SettingsVisitor& v) { devices.visit(v); }},
            {"atmosphere", [this](SettingsVisitor& v) { atmosphere.visit(v); }},
            {"terrain", [this](SettingsVisitor& v) { terrain.visit(v); }},
            {"shadows", [this](SettingsVisitor& v) { shadows.visit(v); }},
            {"lightShafts", [this](SettingsVisitor& v) { lightShafts.visit(v); }},
            {"clouds", [this](SettingsVisitor& v) { clouds.visit(v); }},
            {"toneMapping", [this](SettingsVisitor& v) { toneMapping.visit(v); }},
            {"shaders", [this](SettingsVisitor& v) { shaders.visit(v); }},
            {"ui", [this](SettingsVisitor& v) { ui.visit(v); }}};
}

void State::storeBookmark(int slot) { bookmarks.at(static_cast<size_t>(slot - 1)) = Bookmark{camera, sun}; }

bool State::recallBookmark(int slot) {
    const auto& bookmark = bookmarks.at(static_cast<size_t>(slot - 1));
    if (!bookmark) return false;
    camera = bookmark->camera;
    sun = bookmark->sun;
    return true;
}

json stateToJson(State& state) {
    json out = {{"format", kStateFormat}};
    out.update(settingsToJson(state.sections()));
    json bookmarks = json::object();
    for (int slot = 1; slot <= kBookmarkSlots; ++slot) {
        auto& bookmark = state.bookmarks[static_cast<size_t>(slot - 1)];
        if (bookmark) bookmarks[std::to_string(slot)] = settingsToJson(bookmark->sections());
    }
    if (!bookmarks.empty()) out["bookmarks"] = bookmarks;
    return out;
}

void stateFromJson(State& state, const json& in) {
    if (!in.is_object()) throw SettingsError("expected a JSON object at the top, got " + in.dump().substr(0, 40));
    State next = state;
    json sections = in;
    if (const auto format = sections.find("format"); format != sections.end()) {
        if (!format->is_number_integer() || format->get<int>() != kStateFormat)
            throw SettingsError("format: " + format->dump() + " is not a state format this version reads (" +
                                std::to_string(kStateFormat) + ")");
        sections.erase(format);
    }
    if (const auto bookmarks = sections.find("bookmarks"); bookmarks != sections.end()) {
        if (!bookmarks->is_object()) throw SettingsError("bookmarks: expected an object with keys \"1\" to \"9\"");
        for (const auto& [slot, value] : bookmarks->items()) {
            const int index = slot.size() == 1 && slot[0] >= '1' && slot[0] <= '9' ? slot[0] - '0' : 0;
            if (!index) throw SettingsError("bookmarks: '" + slot + "' is not a slot from 1 to 9");
            Bookmark bookmark{next.camera, next.sun};
            try {
                settingsFromJson(value, bookmark.sections());
            } catch (const SettingsError& e) {
                throw SettingsError("bookmarks." + slot + "." + e.what());
            }
            next.bookmarks[static_cast<size_t>(index - 1)] = bookmark;
        }
        sections.erase(bookmarks);
    }
    settingsFromJson(sections, next.sections());
    state = next;
}

void saveStateFile(State& state, const std::filesystem::path& path) {
    const std::string text = stateToJson(state).dump(2) + "\n";
    writeFileText(path, text);
}

void loadStateFile(State& state, const std::filesystem::path& path) { parseStateFile(state, readFileBytes(path), path.string()); }

void parseStateFile(State& state, std::span<const std::uint8_t> bytes, const std::string& name) {
    json parsed;
    try {
        parsed = json::parse(bytes.begin(), bytes.end());
    } catch (const json::exception& e) {  // parse_error names the line and column; out_of_range a number too large for a double
        throw SettingsError(name + ": not valid JSON: " + e.what());
    }
    try {
        stateFromJson(state, parsed);
    } catch (const SettingsError& e) {
        throw SettingsError(name + ": " + e.what());
    }
}

void applyAssignments(State& state, const std::vector<std::string>& assignments) {
    State next = state;
    for (const std::string& assignment : assignments) {
        try {
            assignSetting(assignment, next.sections());
        } catch (const SettingsError& e) {
            throw SettingsError("--set " + assignment + ": " + e.what());
        }
    }
    state = next;
}

}  // namespace firmament
