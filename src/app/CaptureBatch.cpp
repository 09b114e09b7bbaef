#include "app/CaptureBatch.h"

#include "app/CommandLine.h"
#include "core/FileIO.h"
#include "core/SettingsJson.h"

#include <algorithm>
#include <cctype>

namespace firmament {

using nlohmann::json;

namespace {

constexpr int kMaxFrames = 100000;

// Names become parts of file names: letters, digits, '-', '_' and '.', not starting with '.'.
bool usableName(const std::string& name) {
    if (name.empty() || name.size() > 120 || name[0] == '.') return false;
    return std::all_of(name.begin(), name.end(),
                       [](unsigned char c) { return std::isalnum(c) || c == '-' || c == '_' || c == '.'; });
}

class Fields {
public:
    explicit Fields(std::string where) : where_(std::move(where)) {}
    [[noreturn]] void fail(const std::string& key, const std::string& why) const { throw SettingsError(where_ + ": " + key + ": " + why); }

    // A [width, height] within the frame's limits, or `fallback` when absent.
    void size(const json& object, const std::string& path, int& width, int& height) const {
        if (!object.contains("resolution")) return;
        const json& s = object["resolution"];
        const auto side = [](const json& v) {
            return v.is_number_integer() && v.get<long long>() >= kMinFrameSide && v.get<long long>() <= kMaxFrameSide;
        };
        if (!s.is_array() || s.size() != 2 || !side(s[0]) || !side(s[1]))
            fail(path + "resolution", s.dump() + " is not [width, height] with each from " + std::to_string(kMinFrameSide) + " to " +
                                          std::to_string(kMaxFrameSide));
        width = s[0].get<int>();
        height = s[1].get<int>();
    }
    void frames(const json& object, const std::string& path, int& frames) const {
        if (!object.contains("frames")) return;
        const json& f = object["frames"];
        if (!f.is_number_integer() || f.get<long long>() < 1 || f.get<long long>() > kMaxFrames)
            fail(path + "frames", "expected a whole number from 1 to " + std::to_string(kMaxFrames) + ", got " + f.dump());
        frames = f.get<int>();
    }
    void flag(const json& object, const std::string& key, const std::string& path, bool& value) const {
        if (!object.contains(key)) return;
        if (!object[key].is_boolean()) fail(path + key, "expected true or false, got " + object[key].dump());
        value = object[key].get<bool>();
    }
    std::string name(const json& object, const std::string& key, const std::string& path) const {
        if (!object.contains(key)) fail(path + key, "is missing");
        const json& n = object[key];
        if (!n.is_string() || !usableName(n.get<std::string>()))
            fail(path + key, n.dump() + " is not a name of letters, digits, '-', '_' and '.' (it names the view's files)");
        return n.get<std::string>();
    }
    // The defaults' state with the view's "settings" fragment, then its "set" assignments.
    State state(const json& object, const std::string& path, const State& base) const {
        State state = base;
        const json& fragment = object.value("settings", json::object());
        if (!fragment.is_object()) fail(path + "settings", "expected a state fragment (an object)");
        const json& assignments = object.value("set", json::array());
        if (!assignments.is_array()) fail(path + "set", "expected a list of \"section.key=value\"");
        std::vector<std::string> set;
        for (const json& a : assignments) {
            if (!a.is_string()) fail(path + "set", "expected \"section.key=value\" strings, got " + a.dump());
            set.push_back(a.get<std::string>());
        }
        try {
            stateFromJson(state, fragment);
            applyAssignments(state, set);
        } catch (const SettingsError& e) {
            fail(path + "settings", e.what());
        }
        return state;
    }

private:
    std::string where_;
};

}  // namespace

std::vector<CaptureItem> parseCaptureBatch(const json& in, const CaptureDefaults& defaults, const std::string& where) {
    const Fields f(where);
    if (!in.is_object()) f.fail("(top)", "expected a JSON object with a list of \"views\"");
    CaptureDefaults file = defaults;
    f.size(in, "", file.width, file.height);
    f.frames(in, "", file.frames);
    f.flag(in, "captureUi", "", file.captureUi);
    if (!in.contains("views") || !in["views"].is_array() || in["views"].empty())
        f.fail("views", "expected a non-empty list of {\"name\": ..., \"settings\": {...}}");
    std::vector<CaptureItem> items;
    const json& views = in["views"];
    for (size_t i = 0; i < views.size(); ++i) {
        const std::string path = "views[" + std::to_string(i) + "].";
        if (!views[i].is_object()) f.fail(path, "expected an object");
        CaptureItem item;
        item.id = f.name(views[i], "name", path);
        if (std::any_of(items.begin(), items.end(), [&](const CaptureItem& o) { return o.id == item.id; }))
            f.fail(path + "name", "'" + item.id + "' is used twice (its files would be written twice)");
        item.width = file.width;
        item.height = file.height;
        item.frames = file.frames;
        f.size(views[i], path, item.width, item.height);
        f.frames(views[i], path, item.frames);
        item.captureUi = file.captureUi;
        f.flag(views[i], "captureUi", path, item.captureUi);
        item.state = f.state(views[i], path, defaults.state);
        // --capture's PATH-name, as a flight's named captures (Options::capturePng).
        item.png = defaults.capture;
        // Built whole, not with replace_extension: a name such as "b.2" has a dot of its own.
        item.png.replace_filename(defaults.capture.stem().string() + "-" + item.id + ".png");
        items.push_back(std::move(item));
    }
    return items;
}

std::vector<CaptureItem> loadCaptureBatch(const std::filesystem::path& path, const CaptureDefaults& defaults) {
    return parseCaptureBatch(parseJsonDocument(readFileBytes(path), path.string()), defaults, path.string());
}

CaptureItem parseCaptureRequest(const std::string& line, const CaptureDefaults& defaults) {
    json in;
    try {
        in = json::parse(line);
    } catch (const json::exception& e) {
        throw SettingsError(std::string("a request that is not valid JSON: ") + e.what());
    }
    if (!in.is_object()) throw SettingsError("a request that is not a JSON object: " + line);
    const bool hasId = in.contains("id");
    const Fields f(hasId && in["id"].is_string() ? "request '" + in["id"].get<std::string>() + "'" : std::string("request"));
    CaptureItem item;
    item.id = f.name(in, hasId ? "id" : "name", "");
    item.width = defaults.width;
    item.height = defaults.height;
    item.frames = defaults.frames;
    f.size(in, "", item.width, item.height);
    f.frames(in, "", item.frames);
    item.captureUi = defaults.captureUi;
    f.flag(in, "captureUi", "", item.captureUi);
    item.state = f.state(in, "", defaults.state);
    if (!in.contains("capture") || !in["capture"].is_string() || in["capture"].get<std::string>().empty())
        f.fail("capture", "expected the PNG's path (the EXR is written beside it)");
    item.png = std::filesystem::path(in["capture"].get<std::string>());
    if (item.png.extension() != ".png") f.fail("capture", "'" + item.png.string() + "' does not end in .png");
    return item;
}

std::string captureRequestId(const std::string& line) {
    const json in = json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (!in.is_object()) return "?";
    for (const char* key : {"id", "name"})
        if (in.contains(key) && in[key].is_string() && usableName(in[key].get<std::string>())) return in[key].get<std::string>();
    return "?";
}

}  // namespace firmament
