#pragma once
// What a technique's panel section draws with: the GUI's model (the state and what the program
// reports), the settings sections of the state, and the requests it may make. editSettings()
// draws a section's fields through the same listing JSON and --set use; a section or key that
// does not exist throws SettingsError naming it, so that a mistyped key fails the first frame
// that draws it (and the panel test, tests/unit/PanelsTest.cpp), never reads past a list.
#include "core/SettingsJson.h"
#include "ui/Panels.h"

#include <initializer_list>
#include <string_view>
#include <vector>

namespace firmament {

struct PanelContext {
    GuiModel& model;
    const std::vector<SettingsSection>& sections;
    GuiRequests& requests;
};

// The named section; throws SettingsError when there is none.
const SettingsSection& settingsSection(const std::vector<SettingsSection>& sections, std::string_view name);

// Widgets for the listed keys of a section (all of them when none are listed), in the section's
// order; true when one changed. Throws SettingsError for a section or key that does not exist.
bool editSettings(PanelContext& panel, std::string_view section, std::initializer_list<std::string_view> keys = {});

}  // namespace firmament
