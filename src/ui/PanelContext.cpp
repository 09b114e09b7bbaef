#include "ui/PanelContext.h"

#include "ui/SettingsEditor.h"

#include <algorithm>
#include <string>

namespace firmament {

const SettingsSection& settingsSection(const std::vector<SettingsSection>& sections, std::string_view name) {
    const auto found = std::find_if(sections.begin(), sections.end(), [&](const SettingsSection& s) { return s.name == name; });
    if (found == sections.end()) throw SettingsError("GUI: there is no settings section '" + std::string(name) + "'");
    return *found;
}

bool editSettings(PanelContext& panel, std::string_view section, std::initializer_list<std::string_view> keys) {
    return editSection(settingsSection(panel.sections, section), keys);
}

}  // namespace firmament
