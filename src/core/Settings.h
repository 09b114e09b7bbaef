#pragma once
// Settings are plain structs with defaults; each lists its fields, with their ranges, to a
// SettingsVisitor. The same listing drives JSON load and save, `--set section.key=value`
// and the GUI's widgets, so a field is declared once.
#include <glm/vec3.hpp>

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace firmament {

template <typename T>
struct Range {
    T min;
    T max;
    bool logarithmic = false;  // GUI hint: a slider over orders of magnitude

    bool contains(T value) const { return value >= min && value <= max; }
};

class SettingsVisitor {
public:
    virtual ~SettingsVisitor() = default;
    virtual void field(std::string_view key, bool& value, std::string_view label) = 0;
    virtual void field(std::string_view key, int& value, Range<int> range, std::string_view label) = 0;
    virtual void field(std::string_view key, float& value, Range<float> range, std::string_view label) = 0;
    // Any finite vector (a position, a direction).
    virtual void field(std::string_view key, glm::vec3& value, std::string_view label) = 0;
    // A linear RGB colour, each component in [0, 1]: saved and set like a vector, edited with a
    // colour picker.
    virtual void colour(std::string_view key, glm::vec3& value, std::string_view label) { field(key, value, label); }
    // One of `names`, stored as its index.
    virtual void choiceIndex(std::string_view key, int& index, std::span<const std::string_view> names,
                             std::string_view label) = 0;

    // A power of two, `smallest << i` for the i-th of `names`, chosen by name: the value shows as
    // the smallest choice not below it.
    void powerOfTwoChoice(std::string_view key, int& value, int smallest, std::span<const std::string_view> names, std::string_view label) {
        int index = 0;
        while (index + 1 < static_cast<int>(names.size()) && (smallest << index) < value) ++index;
        choiceIndex(key, index, names, label);
        value = smallest << index;
    }

    template <typename Enum>
    void choice(std::string_view key, Enum& value, std::span<const std::string_view> names, std::string_view label) {
        int index = static_cast<int>(value);
        choiceIndex(key, index, names, label);
        value = static_cast<Enum>(index);
    }
};

// A named group of fields ("camera", "sun", ...): the first part of a settings key.
struct SettingsSection {
    std::string_view name;
    std::function<void(SettingsVisitor&)> visit;
};

}  // namespace firmament
