#include "ui/SettingsEditor.h"

#include "core/SettingsJson.h"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

namespace firmament {

namespace {

std::string text(std::string_view s) { return std::string(s); }

// Forwards only the listed keys to the editor.
class FilteredEditor final : public SettingsVisitor {
public:
    FilteredEditor(SettingsEditor& editor, std::initializer_list<std::string_view> only) : editor_(editor), only_(only) {}
    void field(std::string_view k, bool& v, std::string_view l) override {
        if (wanted(k)) editor_.field(k, v, l);
    }
    void field(std::string_view k, int& v, Range<int> r, std::string_view l) override {
        if (wanted(k)) editor_.field(k, v, r, l);
    }
    void field(std::string_view k, float& v, Range<float> r, std::string_view l) override {
        if (wanted(k)) editor_.field(k, v, r, l);
    }
    void field(std::string_view k, glm::vec3& v, std::string_view l) override {
        if (wanted(k)) editor_.field(k, v, l);
    }
    void colour(std::string_view k, glm::vec3& v, std::string_view l) override {
        if (wanted(k)) editor_.colour(k, v, l);
    }
    void choiceIndex(std::string_view k, int& i, std::span<const std::string_view> n, std::string_view l) override {
        if (wanted(k)) editor_.choiceIndex(k, i, n, l);
    }

    // The first listed key that no field had, or an empty view.
    std::string_view missingKey() const {
        for (std::string_view key : only_)
            if (std::find(seen_.begin(), seen_.end(), key) == seen_.end()) return key;
        return {};
    }

private:
    bool wanted(std::string_view key) {
        seen_.push_back(key);
        return only_.size() == 0 || std::find(only_.begin(), only_.end(), key) != only_.end();
    }
    SettingsEditor& editor_;
    std::initializer_list<std::string_view> only_;
    std::vector<std::string_view> seen_;
};

}  // namespace

void SettingsEditor::field(std::string_view, bool& value, std::string_view label) {
    changed_ |= ImGui::Checkbox(text(label).c_str(), &value);
}

void SettingsEditor::field(std::string_view, int& value, Range<int> range, std::string_view label) {
    changed_ |= ImGui::SliderInt(text(label).c_str(), &value, range.min, range.max, "%d", ImGuiSliderFlags_AlwaysClamp);
}

void SettingsEditor::field(std::string_view, float& value, Range<float> range, std::string_view label) {
    const ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | (range.logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
    changed_ |= ImGui::SliderFloat(text(label).c_str(), &value, range.min, range.max, "%.3g", flags);
}

void SettingsEditor::field(std::string_view, glm::vec3& value, std::string_view label) {
    changed_ |= ImGui::DragFloat3(text(label).c_str(), &value.x, 10.0f, 0.0f, 0.0f, "%.1f");
}

void SettingsEditor::colour(std::string_view, glm::vec3& value, std::string_view label) {
    changed_ |= ImGui::ColorEdit3(text(label).c_str(), &value.x, ImGuiColorEditFlags_Float);
}

void SettingsEditor::choiceIndex(std::string_view, int& index, std::span<const std::string_view> names, std::string_view label) {
    if (!ImGui::BeginCombo(text(label).c_str(), text(names[static_cast<size_t>(index)]).c_str())) return;
    for (size_t i = 0; i < names.size(); ++i) {
        const bool selected = static_cast<int>(i) == index;
        if (ImGui::Selectable(text(names[i]).c_str(), selected) && !selected) {
            index = static_cast<int>(i);
            changed_ = true;
        }
    }
    ImGui::EndCombo();
}

bool editSection(const SettingsSection& section, std::initializer_list<std::string_view> only) {
    SettingsEditor editor;
    FilteredEditor filtered(editor, only);
    ImGui::PushID(text(section.name).c_str());
    section.visit(filtered);
    ImGui::PopID();
    if (const std::string_view key = filtered.missingKey(); !key.empty())
        throw SettingsError("GUI: the settings section '" + text(section.name) + "' has no key '" + text(key) + "'");
    return editor.changed();
}

}  // namespace firmament
