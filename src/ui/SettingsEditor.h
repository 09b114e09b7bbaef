#pragma once
// Dear ImGui widgets for a settings section, from the same listing that JSON and --set use:
// a checkbox for a bool, a slider clamped to the field's range for a number, a combo for a
// choice, a drag field for a vector.
#include "core/Settings.h"

namespace firmament {

class SettingsEditor final : public SettingsVisitor {
public:
    void field(std::string_view key, bool& value, std::string_view label) override;
    void field(std::string_view key, int& value, Range<int> range, std::string_view label) override;
    void field(std::string_view key, float& value, Range<float> range, std::string_view label) override;
    void field(std::string_view key, glm::vec3& value, std::string_view label) override;
    void colour(std::string_view key, glm::vec3& value, std::string_view label) override;
    void choiceIndex(std::string_view key, int& index, std::span<const std::string_view> names, std::string_view label) override;

    bool changed() const { return changed_; }

private:
    bool changed_ = false;
};

// Draws every field of `section`, or only those whose keys are listed in `only`; true when one
// changed. A listed key the section does not have throws SettingsError naming it.
bool editSection(const SettingsSection& section, std::initializer_list<std::string_view> only = {});

}  // namespace firmament
