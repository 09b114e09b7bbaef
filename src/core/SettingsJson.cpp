#include "core/SettingsJson.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

namespace firmament {

using nlohmann::json;

namespace {

// A float as the shortest decimal that reads back to the same float, so saved files are
// readable (0.1, not 0.100000001490116) and round trips are exact.
json shortestNumber(float value) {
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof(text), value);
    return ec == std::errc() ? json(std::strtod(std::string(text, end).c_str(), nullptr)) : json(value);
}

std::string describe(const json& value) {
    const std::string text = value.dump();
    return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

std::string formatNumber(double value) {
    std::ostringstream s;
    s << value;
    return s.str();
}

std::string lowercase(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::string joinNames(std::span<const std::string_view> names) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + std::string(names[i]);
    return out;
}

bool isColour(const glm::vec3& c) {
    return c.x >= 0.0f && c.x <= 1.0f && c.y >= 0.0f && c.y <= 1.0f && c.z >= 0.0f && c.z <= 1.0f;
}

std::string outOfRange(const std::string& key, double value, double min, double max) {
    return key + ": " + formatNumber(value) + " is outside " + formatNumber(min) + " to " + formatNumber(max);
}

class JsonWriter final : public SettingsVisitor {
public:
    explicit JsonWriter(json& out) : out_(out) {}
    void field(std::string_view key, bool& value, std::string_view) override { out_[std::string(key)] = value; }
    void field(std::string_view key, int& value, Range<int>, std::string_view) override { out_[std::string(key)] = value; }
    void field(std::string_view key, float& value, Range<float>, std::string_view) override {
        out_[std::string(key)] = shortestNumber(value);
    }
    void field(std::string_view key, glm::vec3& value, std::string_view) override {
        out_[std::string(key)] = json::array({shortestNumber(value.x), shortestNumber(value.y), shortestNumber(value.z)});
    }
    void choiceIndex(std::string_view key, int& index, std::span<const std::string_view> names, std::string_view) override {
        out_[std::string(key)] = std::string(names[static_cast<size_t>(index)]);
    }

private:
    json& out_;
};

// Reads the fields present in one section's object; remembers which keys it used.
class JsonReader final : public SettingsVisitor {
public:
    JsonReader(const json& in, std::string_view section) : in_(in), section_(section) {}

    void field(std::string_view key, bool& value, std::string_view) override {
        if (const json* v = find(key)) {
            if (!v->is_boolean()) fail(key, "expected true or false, got " + describe(*v));
            value = v->get<bool>();
        }
    }
    void field(std::string_view key, int& value, Range<int> range, std::string_view) override {
        if (const json* v = find(key)) {
            if (!v->is_number_integer()) fail(key, "expected a whole number, got " + describe(*v));
            const auto n = v->get<long long>();
            if (n < range.min || n > range.max) throw SettingsError(outOfRange(name(key), double(n), range.min, range.max));
            value = static_cast<int>(n);
        }
    }
    void field(std::string_view key, float& value, Range<float> range, std::string_view) override {
        if (const json* v = find(key)) {
            if (!v->is_number()) fail(key, "expected a number, got " + describe(*v));
            const double n = v->get<double>();
            if (!(n >= range.min && n <= range.max)) throw SettingsError(outOfRange(name(key), n, range.min, range.max));
            value = static_cast<float>(n);
        }
    }
    void field(std::string_view key, glm::vec3& value, std::string_view) override {
        if (const json* v = find(key)) {
            if (!v->is_array() || v->size() != 3 || !std::all_of(v->begin(), v->end(), [](const json& e) { return e.is_number(); }))
                fail(key, "expected three numbers [x, y, z], got " + describe(*v));
            glm::vec3 read((*v)[0].get<float>(), (*v)[1].get<float>(), (*v)[2].get<float>());
            if (!std::isfinite(read.x) || !std::isfinite(read.y) || !std::isfinite(read.z)) fail(key, "is not finite");
            value = read;
        }
    }
    void colour(std::string_view key, glm::vec3& value, std::string_view label) override {
        field(key, value, label);
        if (!isColour(value)) fail(key, "colour components must be within 0 to 1");
    }
    void choiceIndex(std::string_view key, int& index, std::span<const std::string_view> names, std::string_view) override {
        if (const json* v = find(key)) {
            if (!v->is_string()) fail(key, "expected one of " + joinNames(names) + ", got " + describe(*v));
            const std::string text = lowercase(v->get<std::string>());
            const auto it = std::find_if(names.begin(), names.end(), [&](std::string_view n) { return lowercase(n) == text; });
            if (it == names.end()) fail(key, describe(*v) + " is not one of " + joinNames(names));
            index = static_cast<int>(it - names.begin());
        }
    }

    void rejectUnknownKeys() const {
        for (const auto& [key, value] : in_.items())
            if (!used_.count(key)) throw SettingsError("unknown key '" + std::string(section_) + "." + key + "'");
    }

private:
    const json* find(std::string_view key) {
        used_.insert(std::string(key));
        const auto it = in_.find(std::string(key));
        return it == in_.end() ? nullptr : &*it;
    }
    std::string name(std::string_view key) const { return std::string(section_) + "." + std::string(key); }
    [[noreturn]] void fail(std::string_view key, const std::string& why) const { throw SettingsError(name(key) + ": " + why); }

    const json& in_;
    std::string_view section_;
    std::set<std::string> used_;
};

// Finds one key and parses a text value for it.
class TextAssigner final : public SettingsVisitor {
public:
    TextAssigner(std::string_view section, std::string_view key, std::string_view text)
        : section_(section), key_(key), text_(text) {}

    bool found() const { return found_; }

    void field(std::string_view key, bool& value, std::string_view) override {
        if (!match(key)) return;
        const std::string t = lowercase(text_);
        if (t == "on" || t == "true" || t == "1") value = true;
        else if (t == "off" || t == "false" || t == "0") value = false;
        else fail("expected on or off, got '" + std::string(text_) + "'");
    }
    void field(std::string_view key, int& value, Range<int> range, std::string_view) override {
        if (!match(key)) return;
        long long n = 0;
        const auto [end, ec] = std::from_chars(text_.data(), text_.data() + text_.size(), n);
        if (ec != std::errc() || end != text_.data() + text_.size() || text_.empty())
            fail("expected a whole number, got '" + std::string(text_) + "'");
        if (n < range.min || n > range.max) throw SettingsError(outOfRange(name(), double(n), range.min, range.max));
        value = static_cast<int>(n);
    }
    void field(std::string_view key, float& value, Range<float> range, std::string_view) override {
        if (!match(key)) return;
        const float n = parseFloat(text_);
        if (!range.contains(n)) throw SettingsError(outOfRange(name(), n, range.min, range.max));
        value = n;
    }
    void field(std::string_view key, glm::vec3& value, std::string_view) override {
        if (!match(key)) return;
        std::vector<std::string_view> parts;
        size_t start = 0;
        for (size_t comma; (comma = text_.find(',', start)) != std::string_view::npos; start = comma + 1)
            parts.push_back(text_.substr(start, comma - start));
        parts.push_back(text_.substr(start));
        if (parts.size() != 3) fail("expected x,y,z, got '" + std::string(text_) + "'");
        value = glm::vec3(parseFloat(parts[0]), parseFloat(parts[1]), parseFloat(parts[2]));
    }
    void colour(std::string_view key, glm::vec3& value, std::string_view label) override {
        field(key, value, label);
        if (match(key) && !isColour(value)) fail("colour components must be within 0 to 1");
    }
    void choiceIndex(std::string_view key, int& index, std::span<const std::string_view> names, std::string_view) override {
        if (!match(key)) return;
        const std::string t = lowercase(text_);
        const auto it = std::find_if(names.begin(), names.end(), [&](std::string_view n) { return lowercase(n) == t; });
        if (it == names.end()) fail("'" + std::string(text_) + "' is not one of " + joinNames(names));
        index = static_cast<int>(it - names.begin());
    }

private:
    bool match(std::string_view key) {
        if (key != key_) return false;
        found_ = true;
        return true;
    }
    float parseFloat(std::string_view text) const {
        float n = 0.0f;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
        if (ec != std::errc() || end != text.data() + text.size() || text.empty() || !std::isfinite(n))
            fail("expected a number, got '" + std::string(text) + "'");
        return n;
    }
    std::string name() const { return std::string(section_) + "." + std::string(key_); }
    [[noreturn]] void fail(const std::string& why) const { throw SettingsError(name() + ": " + why); }

    std::string_view section_, key_, text_;
    bool found_ = false;
};

class KeyLister final : public SettingsVisitor {
public:
    KeyLister(std::string_view section, std::vector<std::string>& keys) : section_(section), keys_(keys) {}
    void field(std::string_view key, bool&, std::string_view) override { add(key); }
    void field(std::string_view key, int&, Range<int>, std::string_view) override { add(key); }
    void field(std::string_view key, float&, Range<float>, std::string_view) override { add(key); }
    void field(std::string_view key, glm::vec3&, std::string_view) override { add(key); }
    void choiceIndex(std::string_view key, int&, std::span<const std::string_view>, std::string_view) override { add(key); }

private:
    void add(std::string_view key) { keys_.push_back(std::string(section_) + "." + std::string(key)); }
    std::string_view section_;
    std::vector<std::string>& keys_;
};

const SettingsSection* findSection(std::span<const SettingsSection> sections, std::string_view name) {
    const auto it = std::find_if(sections.begin(), sections.end(), [&](const SettingsSection& s) { return s.name == name; });
    return it == sections.end() ? nullptr : &*it;
}

std::string sectionNames(std::span<const SettingsSection> sections) {
    std::string out;
    for (const SettingsSection& s : sections) out += (out.empty() ? "" : ", ") + std::string(s.name);
    return out;
}

}  // namespace

json settingsToJson(std::span<const SettingsSection> sections) {
    json out = json::object();
    for (const SettingsSection& section : sections) {
        json& fields = out[std::string(section.name)] = json::object();
        JsonWriter writer(fields);
        section.visit(writer);
    }
    return out;
}

void settingsFromJson(const json& in, std::span<const SettingsSection> sections) {
    if (!in.is_object()) throw SettingsError("expected an object of sections, got " + describe(in));
    for (const auto& [name, fields] : in.items()) {
        const SettingsSection* section = findSection(sections, name);
        if (!section) throw SettingsError("unknown section '" + name + "' (sections: " + sectionNames(sections) + ")");
        if (!fields.is_object()) throw SettingsError(name + ": expected an object of keys, got " + describe(fields));
        JsonReader reader(fields, section->name);
        section->visit(reader);
        reader.rejectUnknownKeys();
    }
}

void assignSetting(std::string_view assignment, std::span<const SettingsSection> sections) {
    const auto eq = assignment.find('=');
    const auto dot = assignment.find('.');
    if (eq == std::string_view::npos || dot == std::string_view::npos || dot > eq)
        throw SettingsError("'" + std::string(assignment) + "' is not section.key=value");
    const std::string_view sectionName = assignment.substr(0, dot);
    const std::string_view key = assignment.substr(dot + 1, eq - dot - 1);
    const std::string_view value = assignment.substr(eq + 1);
    const SettingsSection* section = findSection(sections, sectionName);
    if (!section)
        throw SettingsError("unknown section '" + std::string(sectionName) + "' (sections: " + sectionNames(sections) + ")");
    TextAssigner assigner(sectionName, key, value);
    section->visit(assigner);
    if (!assigner.found()) {
        std::vector<std::string> keys;
        KeyLister lister(section->name, keys);
        section->visit(lister);
        std::string known;
        for (const std::string& k : keys) known += (known.empty() ? "" : ", ") + k;
        throw SettingsError("unknown key '" + std::string(sectionName) + "." + std::string(key) + "' (known: " + known + ")");
    }
}

std::vector<std::string> settingKeys(std::span<const SettingsSection> sections) {
    std::vector<std::string> keys;
    for (const SettingsSection& section : sections) {
        KeyLister lister(section.name, keys);
        section.visit(lister);
    }
    return keys;
}

nlohmann::json parseJsonDocument(std::span<const std::uint8_t> bytes, const std::string& name) {
    try {
        return nlohmann::json::parse(bytes.begin(), bytes.end());
    } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for a number too large for a double
        throw SettingsError(name + ": not valid JSON: " + e.what());
    }
}

}  // namespace firmament
