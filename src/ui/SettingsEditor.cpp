#include "ui/SettingsEditor.h"

#include <imgui.h>

#include <algorithm>
#include <string>

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

private:
    bool wanted(std::string_view key) const {
        return only_.size() == 0 || std::find(only_.begin(), only_.end(), key) != only_.end();
    }
    SettingsEditor& editor_;
    std::initializer_list<std::string_view> only_;
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
    return editor.changed();
}

}  // namespace firmament
