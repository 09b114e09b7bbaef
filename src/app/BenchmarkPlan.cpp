#include "app/BenchmarkPlan.h"

#include "core/FileIO.h"
#include "core/SettingsJson.h"

#include <algorithm>

namespace firmament {

using nlohmann::json;

namespace {

constexpr int kFormat = 1;

class Reader {
public:
    explicit Reader(std::string where) : where_(std::move(where)) {}

    [[noreturn]] void fail(const std::string& key, const std::string& why) const { throw SettingsError(where_ + ": " + key + ": " + why); }

    const json& field(const json& object, const std::string& key, const std::string& path) const {
        if (!object.contains(key)) fail(path + key, "is missing");
        return object[key];
    }
    int integer(const json& object, const std::string& key, int low, int high, int fallback) const {
        if (!object.contains(key)) return fallback;
        const json& v = object[key];
        if (!v.is_number_integer() || v.get<long long>() < low || v.get<long long>() > high)
            fail(key, "expected a whole number from " + std::to_string(low) + " to " + std::to_string(high) + ", got " + v.dump());
        return v.get<int>();
    }
    std::string text(const json& object, const std::string& key, const std::string& path) const {
        const json& v = field(object, key, path);
        if (!v.is_string() || v.get<std::string>().empty()) fail(path + key, "expected a non-empty string, got " + v.dump());
        return v.get<std::string>();
    }
    std::vector<BenchmarkFragment> fragments(const json& object, const std::string& key) const {
        const json& list = field(object, key, "");
        if (!list.is_array() || list.empty()) fail(key, "expected a non-empty list of {\"name\": ..., \"settings\": {...}}");
        std::vector<BenchmarkFragment> out;
        for (size_t i = 0; i < list.size(); ++i) {
            const std::string path = key + "[" + std::to_string(i) + "].";
            if (!list[i].is_object()) fail(path, "expected an object");
            BenchmarkFragment f{text(list[i], "name", path), list[i].value("settings", json::object())};
            if (!f.settings.is_object()) fail(path + "settings", "expected a state fragment (an object)");
            if (std::any_of(out.begin(), out.end(), [&](const BenchmarkFragment& o) { return o.name == f.name; }))
                fail(path + "name", "'" + f.name + "' is used twice");
            out.push_back(std::move(f));
        }
        return out;
    }

private:
    std::string where_;
};

State applied(const State& start, const json& fragment, const std::string& where, const std::string& what) {
    State state = start;
    try {
        stateFromJson(state, fragment);
    } catch (const SettingsError& e) {
        throw SettingsError(where + ": " + what + ": " + e.what());
    }
    return state;
}

}  // namespace

BenchmarkPlan parseBenchmarkPlan(const json& in, const State& defaults, const std::string& where) {
    const Reader r(where);
    if (!in.is_object()) r.fail("(top)", "expected a JSON object");
    static const char* known[] = {"format", "name", "description", "warmupFrames", "measuredFrames", "resolutions", "base",
                                  "views", "variants", "ratios", "tables"};
    for (const auto& [key, value] : in.items())
        if (std::find(std::begin(known), std::end(known), key) == std::end(known)) r.fail(key, "is not a field of a scenario file");
    if (in.value("format", kFormat) != kFormat) r.fail("format", "this version reads format " + std::to_string(kFormat));

    BenchmarkPlan plan;
    plan.name = r.text(in, "name", "");
    plan.description = in.value("description", std::string());
    plan.warmupFrames = r.integer(in, "warmupFrames", 0, 10000, plan.warmupFrames);
    plan.measuredFrames = r.integer(in, "measuredFrames", 1, 100000, plan.measuredFrames);
    if (in.contains("tables") && !in["tables"].is_boolean()) r.fail("tables", "expected true or false");
    plan.tables = in.value("tables", false);

    const json& resolutions = r.field(in, "resolutions", "");
    if (!resolutions.is_array() || resolutions.empty()) r.fail("resolutions", "expected a non-empty list of [width, height]");
    for (const json& size : resolutions) {
        if (!size.is_array() || size.size() != 2 || !size[0].is_number_integer() || !size[1].is_number_integer() || size[0].get<int>() < 16 ||
            size[0].get<int>() > 8192 || size[1].get<int>() < 16 || size[1].get<int>() > 8192)
            r.fail("resolutions", size.dump() + " is not [width, height] with each from 16 to 8192");
        plan.resolutions.emplace_back(size[0].get<int>(), size[1].get<int>());
    }
    plan.base = in.value("base", json::object());
    if (!plan.base.is_object()) r.fail("base", "expected a state fragment (an object)");
    plan.views = r.fragments(in, "views");
    plan.variants = r.fragments(in, "variants");

    const json& ratios = in.value("ratios", json::array());
    if (!ratios.is_array()) r.fail("ratios", "expected a list");
    for (size_t i = 0; i < ratios.size(); ++i) {
        const std::string path = "ratios[" + std::to_string(i) + "].";
        const json& entry = ratios[i];
        if (!entry.is_object()) r.fail(path, "expected an object");
        BenchmarkRatio ratio{r.text(entry, "name", path), r.text(entry, "numerator", path), r.text(entry, "denominator", path), {}, {}};
        for (const std::string* variant : {&ratio.numerator, &ratio.denominator})
            if (std::none_of(plan.variants.begin(), plan.variants.end(), [&](const BenchmarkFragment& v) { return v.name == *variant; }))
                r.fail(path, "'" + *variant + "' is not one of the variants");
        const json& passes = entry.value("passes", json::array());
        if (!passes.is_array()) r.fail(path + "passes", "expected a list of pass names");
        for (const json& pass : passes) {
            if (!pass.is_string()) r.fail(path + "passes", "expected pass names, got " + pass.dump());
            ratio.passes.push_back(pass.get<std::string>());
        }
        if (entry.contains("paper")) {
            if (!entry["paper"].is_number()) r.fail(path + "paper", "expected a number");
            ratio.paper = entry["paper"].get<double>();
        }
        plan.ratios.push_back(std::move(ratio));
    }

    plan.baseState = applied(defaults, plan.base, where, "base");
    const State& base = plan.baseState;
    for (const glm::ivec2 resolution : plan.resolutions)
        for (const BenchmarkFragment& view : plan.views) {
            const State seen = applied(base, view.settings, where, "view '" + view.name + "'");
            for (const BenchmarkFragment& variant : plan.variants) {
                BenchmarkScenario s;
                s.view = view.name;
                s.variant = variant.name;
                s.resolution = resolution;
                s.name = view.name + " / " + variant.name + " / " + std::to_string(resolution.x) + "x" + std::to_string(resolution.y);
                s.state = applied(seen, variant.settings, where, "variant '" + variant.name + "'");
                plan.scenarios.push_back(std::move(s));
            }
        }
    return plan;
}

BenchmarkPlan loadBenchmarkPlan(const std::filesystem::path& path, const State& defaults) {
    return parseBenchmarkPlan(parseJsonDocument(readFileBytes(path), path.string()), defaults, path.string());
}

}  // namespace firmament
