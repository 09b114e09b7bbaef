// The soak's schedule and verdict: malformed schedules are refused naming the step; steps are
// due at their frame of every loop and samples are taken at each loop's end; the shipped
// schedule tries every toggle (both values) and every mode (each value) of every section and
// ends each loop where it started; growth after the warm-up beyond a bound fails, naming the
// quantity, and a run too short to judge says so.
#include "app/SoakSchedule.h"
#include "app/SoakVerdict.h"
#include "core/SettingsJson.h"
#include "settings/State.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

namespace firmament {
namespace {

std::span<const std::uint8_t> bytesOf(const std::string& text) {
    return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

std::string refusal(const std::string& text) {
    try {
        SoakSchedule::parse(bytesOf(text), "soak.json");
    } catch (const SettingsError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(SoakSchedule, MalformedSchedulesAreRefusedNamingTheProblem) {
    EXPECT_NE(refusal("{").find("soak.json: not valid JSON"), std::string::npos);
    EXPECT_EQ(refusal(R"({"loops": 3})"), "soak.json: loops: is not a field of a soak schedule");
    EXPECT_EQ(refusal(R"({"loopFrames": 0})"), "soak.json: loopFrames: expected a whole number from 1 to 1000000, got 0");
    EXPECT_EQ(refusal(R"({"loopFrames": 10, "steps": [{"frame": 10, "set": ["ui.help=on"]}]})"),
              "soak.json: steps[0].frame: expected a whole number from 0 to 9, got 10");
    EXPECT_EQ(refusal(R"({"steps": [{"frame": 5, "set": ["ui.help=on"]}, {"frame": 4, "set": ["ui.help=off"]}]})"),
              "soak.json: steps[1].frame: 4 comes before the step above (5)");
    EXPECT_EQ(refusal(R"({"steps": [{"frame": 1, "set": []}]})"), "soak.json: steps[0].set: expected a non-empty list of \"section.key=value\"");
    EXPECT_EQ(refusal(R"({"steps": [{"frame": 1}]})"), "soak.json: steps[0].set: expected a non-empty list of \"section.key=value\"");
    // The assignment and the settings' own message.
    EXPECT_EQ(refusal(R"({"steps": [{"frame": 1, "set": ["ui.help=on", "clouds.enabled=maybe"]}]})"),
              "soak.json: steps[0].set: clouds.enabled=maybe: clouds.enabled: expected on or off, got 'maybe'");
    EXPECT_EQ(refusal(R"({"bounds": {"objects": 1}})"), "soak.json: bounds.objects: is not a bound (liveObjects, handles, privateMiB)");
    EXPECT_EQ(refusal(R"({"bounds": {"privateMiB": -1}})"), "soak.json: bounds.privateMiB: expected a number of MiB, 0 or more, got -1");
    EXPECT_EQ(refusal(R"({"format": 2})"), "soak.json: format: this version reads format 1");
    const std::string base = refusal(R"({"base": ["clouds.rings=99"]})");
    EXPECT_EQ(base.rfind("soak.json: base: clouds.rings=99: clouds.rings: ", 0), 0u) << base;
    EXPECT_EQ(refusal(R"({"steps": [{"frame": 1, "set": ["ui.help=on"]}]})"), "accepted");
}

TEST(SoakSchedule, StepsAreDueAtTheirFrameOfEveryLoopAndSamplesAtEachLoopsEnd) {
    const SoakSchedule s = SoakSchedule::parse(
        bytesOf(R"({"loopFrames": 10, "warmupLoops": 2, "bounds": {"liveObjects": 3, "handles": 4, "privateMiB": 1.5},
                    "steps": [{"frame": 0, "set": ["ui.help=on"]}, {"frame": 3, "set": ["ui.help=off", "scene.orientationGrid=off"]},
                              {"frame": 3, "set": ["scene.orientationGrid=on"]}]})"),
        "soak.json");
    EXPECT_EQ(s.loopFrames, 10);
    EXPECT_EQ(s.warmupLoops, 2);
    EXPECT_EQ(s.bounds.liveObjects, 3);
    EXPECT_EQ(s.bounds.handles, 4);
    EXPECT_DOUBLE_EQ(s.bounds.privateMiB, 1.5);
    EXPECT_EQ(s.assignmentsAt(0), std::vector<std::string>{"ui.help=on"});
    EXPECT_EQ(s.assignmentsAt(20), std::vector<std::string>{"ui.help=on"});
    EXPECT_TRUE(s.assignmentsAt(1).empty());
    const std::vector<std::string> three{"ui.help=off", "scene.orientationGrid=off", "scene.orientationGrid=on"};
    EXPECT_EQ(s.assignmentsAt(13), three);
    EXPECT_FALSE(s.samplesAfter(8));
    EXPECT_TRUE(s.samplesAfter(9));
    EXPECT_TRUE(s.samplesAfter(29));
    EXPECT_EQ(s.samplesNeeded(), 3);
    EXPECT_EQ(s.framesNeeded(), 30);
}

// Every toggle's and mode's values as the state shows them ("clouds.enabled" -> {"false", "true"}).
class ValuesSeen : public SettingsVisitor {
public:
    std::map<std::string, std::set<std::string>> seen;       // what the state held
    std::map<std::string, std::set<std::string>> possible;   // every value each could hold
    std::string section;

    void field(std::string_view key, bool& value, std::string_view) override {
        const std::string k = section + "." + std::string(key);
        seen[k].insert(value ? "on" : "off");
        possible[k] = {"on", "off"};
    }
    void field(std::string_view, int&, Range<int>, std::string_view) override {}
    void field(std::string_view, float&, Range<float>, std::string_view) override {}
    void field(std::string_view, glm::vec3&, std::string_view) override {}
    void choiceIndex(std::string_view key, int& index, std::span<const std::string_view> names, std::string_view) override {
        const std::string k = section + "." + std::string(key);
        seen[k].insert(std::string(names[static_cast<size_t>(index)]));
        for (std::string_view n : names) possible[k].insert(std::string(n));
    }
    void visit(State& state) {
        for (const SettingsSection& s : state.sections()) {
            section = std::string(s.name);
            s.visit(*this);
        }
    }
};

TEST(SoakSchedule, TheShippedScheduleTriesEveryToggleAndModeAndEndsWhereItStarted) {
    const SoakSchedule s = SoakSchedule::load(test::executableFolder() / "media" / "soak" / "schedule.json");
    ASSERT_FALSE(s.steps.empty());
    State state;
    applyAssignments(state, s.base);
    const State start = state;
    ValuesSeen values;
    values.visit(state);
    for (const SoakStep& step : s.steps) {
        applyAssignments(state, step.assignments);
        values.visit(state);
    }
    for (const auto& [key, all] : values.possible)
        for (const std::string& value : all)
            EXPECT_TRUE(values.seen[key].count(value)) << key << "=" << value << " is never set by media/soak/schedule.json";
    // The loop ends as it began, so every loop's end is sampled in the same state; and the base
    // sets sizes, no toggle or mode (those are the defaults, as a person meets them).
    State begun = start;
    EXPECT_EQ(stateToJson(state), stateToJson(begun));
    ValuesSeen defaults, based;
    State fresh;
    defaults.visit(fresh);
    based.visit(begun);
    EXPECT_EQ(based.seen, defaults.seen);
    // The flight (4 s at 60 Hz) ends with each loop, so that its ends see the same view.
    EXPECT_EQ(s.loopFrames, 240);
    // Steps are held for a frame at least, and the last one before the sample.
    EXPECT_LT(s.steps.back().frame, s.loopFrames - 1);
}

std::vector<SoakSample> flat(int count, long objects, long handles, double mib) {
    std::vector<SoakSample> samples;
    for (int i = 0; i < count; ++i) {
        SoakSample sample;
        sample.frame = 100LL * (i + 1);
        sample.liveObjects = objects;
        sample.handles = handles;
        sample.privateBytes = static_cast<std::uint64_t>(mib * 1024.0 * 1024.0);
        samples.push_back(sample);
    }
    return samples;
}

SoakSchedule schedule(int warmupLoops, SoakBounds bounds) {
    SoakSchedule s;
    s.loopFrames = 100;
    s.warmupLoops = warmupLoops;
    s.bounds = bounds;
    return s;
}

TEST(SoakVerdict, GrowthAfterTheWarmUpBeyondItsBoundFailsNamingTheQuantity) {
    const SoakSchedule s = schedule(2, SoakBounds{0, 2, 8.0});
    // Flat after the warm-up passes, whatever the warm-up did.
    std::vector<SoakSample> samples = flat(6, 400, 50, 200.0);
    samples[0].liveObjects = 350;
    samples[0].privateBytes = 100u << 20;
    EXPECT_TRUE(judgeSoak(samples, s).passed()) << judgeSoak(samples, s).summary();

    // One object more by the last loop: a leak.
    std::vector<SoakSample> leak = flat(6, 400, 50, 200.0);
    leak.back().liveObjects = 401;
    const SoakVerdict v = judgeSoak(leak, s);
    EXPECT_FALSE(v.passed());
    ASSERT_EQ(v.growth.size(), 3u);
    EXPECT_EQ(v.growth[0].quantity, "live D3D11 objects");
    EXPECT_DOUBLE_EQ(v.growth[0].baseline, 400.0);  // the end of the second loop
    EXPECT_DOUBLE_EQ(v.growth[0].growth(), 1.0);
    EXPECT_TRUE(v.growth[0].exceeded());
    EXPECT_FALSE(v.growth[1].exceeded());
    EXPECT_NE(v.summary().find("live D3D11 objects: 400 after the warm-up, at most 401 later (growth 1, bound 0): GREW"), std::string::npos)
        << v.summary();

    // Handles within their bound pass; beyond it fail.
    std::vector<SoakSample> handles = flat(6, 400, 50, 200.0);
    handles[3].handles = 52;
    EXPECT_TRUE(judgeSoak(handles, s).passed());
    handles[4].handles = 53;
    EXPECT_FALSE(judgeSoak(handles, s).passed());
    EXPECT_TRUE(judgeSoak(handles, s).growth[1].exceeded());

    // Private memory is judged by its trend, the rise of the least-squares line through the
    // baseline (sample 1, frame 200) and every later sample, over frames 200 to 600. A steady
    // creep of 2 MiB a loop rises 8 MiB: allowed; 2.125 a loop rises 8.5: not.
    const auto mib = [](double value) { return static_cast<std::uint64_t>(value * 1024.0 * 1024.0); };
    std::vector<SoakSample> memory = flat(6, 400, 50, 200.0);
    for (size_t i = 1; i < memory.size(); ++i) memory[i].privateBytes = mib(200.0 + 2.0 * static_cast<double>(i - 1));
    EXPECT_TRUE(judgeSoak(memory, s).passed()) << judgeSoak(memory, s).summary();
    EXPECT_NEAR(judgeSoak(memory, s).growth[2].growth(), 8.0, 1e-6);
    for (size_t i = 1; i < memory.size(); ++i) memory[i].privateBytes = mib(200.0 + 2.125 * static_cast<double>(i - 1));
    EXPECT_FALSE(judgeSoak(memory, s).passed());
    EXPECT_NEAR(judgeSoak(memory, s).growth[2].growth(), 8.5, 1e-6);
    EXPECT_NE(judgeSoak(memory, s).summary().find("private MiB: 200.0 after the warm-up, at most 208.5 later (fitted rise 8.5, bound 8.0): GREW"),
              std::string::npos)
        << judgeSoak(memory, s).summary();

    // A wander up and down with a peak far above the bound, and no trend, is not growth (the
    // 10,000-frame soak's memory moved so, by 90 MiB, with its floor flat); the same peak on a
    // rising floor is.
    std::vector<SoakSample> wander = flat(6, 400, 50, 200.0);
    wander[2].privateBytes = mib(230.0);
    wander[3].privateBytes = mib(190.0);
    wander[4].privateBytes = mib(230.0);
    wander[5].privateBytes = mib(190.0);
    EXPECT_TRUE(judgeSoak(wander, s).passed()) << judgeSoak(wander, s).summary();
    EXPECT_DOUBLE_EQ(judgeSoak(wander, s).growth[2].peak, 230.0);
    for (size_t i = 3; i < wander.size(); ++i) wander[i].privateBytes += mib(6.0 * static_cast<double>(i - 2));
    EXPECT_FALSE(judgeSoak(wander, s).passed()) << judgeSoak(wander, s).summary();

    // With one sample after the warm-up (the full tier's 1,000 frames), the line is the difference.
    std::vector<SoakSample> shortRun = flat(3, 400, 50, 200.0);
    shortRun[2].privateBytes = mib(208.5);
    EXPECT_NEAR(judgeSoak(shortRun, s).growth[2].growth(), 8.5, 1e-6);
}

TEST(SoakVerdict, ARunTooShortToJudgeSaysSoAndFails) {
    const SoakSchedule s = schedule(2, SoakBounds{});
    const SoakVerdict v = judgeSoak(flat(2, 1, 1, 1.0), s);
    EXPECT_FALSE(v.passed());
    EXPECT_EQ(v.problem, "too few samples to judge: 2 loops of 100 frames were run, and this schedule needs 3 (300 frames; pass more --frames)");
    EXPECT_TRUE(judgeSoak(flat(3, 1, 1, 1.0), s).passed());
    // Without warm-up the first loop's end is the baseline.
    EXPECT_TRUE(judgeSoak(flat(2, 1, 1, 1.0), schedule(0, SoakBounds{})).passed());
}

TEST(SoakVerdict, TheReportHoldsEverySampleAndTheVerdict) {
    const SoakSchedule s = schedule(1, SoakBounds{0, 0, 16.0});
    std::vector<SoakSample> samples = flat(3, 10, 20, 30.0);
    samples[1].liveObjectsByKind = {{"textures", 4}, {"views", 6}};
    const nlohmann::json report = soakReport(s, samples, judgeSoak(samples, s));
    EXPECT_EQ(report["loopFrames"], 100);
    EXPECT_EQ(report["samples"].size(), 3u);
    EXPECT_EQ(report["samples"][1]["liveObjectsByKind"]["views"], 6);
    EXPECT_EQ(report["samples"][2]["frame"], 300);
    EXPECT_EQ(report["growth"][2]["quantity"], "private MiB");
    EXPECT_EQ(report["passed"], true);
}

}  // namespace
}  // namespace firmament
