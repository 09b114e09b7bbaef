#pragma once
// Settings sections to and from JSON (nlohmann-json), and `section.key=value` assignments
// from the command line. Reading is strict: an unknown key, a wrong type or a value out of
// range throws SettingsError naming the key ("camera.fieldOfView: 500 is outside 10 to 120").
// A key missing from the JSON keeps its current value, so a file may hold only a few.
#include "core/Error.h"
#include "core/Settings.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace firmament {

class SettingsError : public Error {
public:
    using Error::Error;
};

nlohmann::json settingsToJson(std::span<const SettingsSection> sections);

// A whole file's bytes as JSON; throws SettingsError "NAME: not valid JSON: ..." (the parser's
// line and column, or a number too large for a double).
nlohmann::json parseJsonDocument(std::span<const std::uint8_t> bytes, const std::string& name);

// `json` is an object of sections; reads into the sections, throws SettingsError.
void settingsFromJson(const nlohmann::json& json, std::span<const SettingsSection> sections);

// One `section.key=value` assignment. Booleans take on/off/true/false/1/0, choices their
// name, vectors "x,y,z".
void assignSetting(std::string_view assignment, std::span<const SettingsSection> sections);

// Every key as "section.key", for messages and documentation.
std::vector<std::string> settingKeys(std::span<const SettingsSection> sections);

}  // namespace firmament
