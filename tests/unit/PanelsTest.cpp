// Every GUI panel, drawn in a Dear ImGui context without a window or a renderer, in every state
// that shows other controls (each atmosphere model and comparison, custom coefficients, manual
// and automatic exposure): a settings key a panel names that does not exist throws, so these
// draws find it. And a missing key or section is an error that names it.
#include "settings/State.h"
#include "ui/PanelContext.h"
#include "ui/Panels.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <string>

namespace firmament {
namespace {

// A Dear ImGui context that draws into nothing: textures stay requests nobody serves.
class HeadlessImGui {
public:
    HeadlessImGui() {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(1280.0f, 720.0f);
        io.DeltaTime = 1.0f / 60.0f;
        io.BackendFlags |= ImGuiBackendFlags_RendererHasTextures;
    }
    ~HeadlessImGui() { ImGui::DestroyContext(); }
    HeadlessImGui(const HeadlessImGui&) = delete;
    HeadlessImGui& operator=(const HeadlessImGui&) = delete;

    // One frame of the whole GUI for `state`.
    void draw(State& state) {
        const std::vector<PassTiming> timings{{"Frame", 1.0, 1.0, 1.0, 1.0, 3, {}}};
        const FrameTimeHistory frameTimes;
        const std::map<std::string, std::string> shaderErrors{{"terrain", "an error"}};
        GuiModel model{state, FrameStats{16.0, 60.0, 1280, 720, "test"}, timings, frameTimes, shaderErrors, "vkd3d-compiler",
                       {"a pad"}, "a notice", false, ExposureReading{true, 0.2f, 0.9f}, 0.5, 0.25,
                       "volume-aware, per-pixel lists: 10 fragments"};
        ImGui::NewFrame();
        drawGui(model);
        ImGui::Render();
    }
};

TEST(Panels, EveryPanelDrawsInEveryStateWithExistingKeys) {
    HeadlessImGui gui;
    for (const Panel panel : {Panel::Basic, Panel::Additional, Panel::ToneMapping, Panel::Clouds, Panel::Performance})
        for (const AtmosphereModel model : {AtmosphereModel::Yusov2013, AtmosphereModel::Bruneton2008, AtmosphereModel::Hillaire2020})
            for (const ModelComparison comparison : {ModelComparison::None, ModelComparison::Split, ModelComparison::Difference, ModelComparison::ThreeWay})
                for (const bool custom : {false, true})
                    for (const LightShaftTechnique technique : {LightShaftTechnique::Epipolar, LightShaftTechnique::BruteForce}) {
                    State state;
                    state.ui.panel = panel;
                    state.ui.help = custom;
                    state.atmosphere.model = model;
                    state.atmosphere.comparison = comparison;
                    state.atmosphere.customCoefficients = custom;
                    state.toneMapping.autoExposure = !custom;
                    // The light shafts' controls show while they are on, the epipolar ones with that technique.
                    state.lightShafts.enabled = custom;
                    state.lightShafts.technique = technique;
                    state.lightShafts.initialStep = 200;  // past samples / 8: the panel says what is used
                    // Past the cascade parts' room: the panel says the single pass is used.
                    state.lightShafts.cascadeProcessing = CascadeProcessing::Instanced;
                    if (custom) {
                        state.lightShafts.slices = 2048;
                        state.lightShafts.samplesPerSlice = 2048;
                    }
                    EXPECT_NO_THROW(gui.draw(state)) << "panel " << static_cast<int>(panel) << ", model " << static_cast<int>(model)
                                                     << ", comparison " << static_cast<int>(comparison) << ", custom " << custom
                                                     << ", technique " << static_cast<int>(technique);
                    }
}

TEST(Panels, AMissingKeyOrSectionIsAnErrorThatNamesIt) {
    HeadlessImGui gui;
    State state;
    const std::vector<SettingsSection> sections = state.sections();
    GuiRequests requests;
    const std::vector<PassTiming> timings;
    const FrameTimeHistory frameTimes;
    const std::map<std::string, std::string> errors;
    GuiModel model{state, {}, timings, frameTimes, errors, "", {}, "", false, {}, std::nullopt, std::nullopt, ""};
    PanelContext panel{model, sections, requests};
    ImGui::NewFrame();
    ImGui::Begin("test");
    EXPECT_NO_THROW(editSettings(panel, "terrain", {"enabled", "view"}));
    try {
        editSettings(panel, "terrain", {"enabled", "enabeld"});
        ADD_FAILURE() << "a misspelt key was accepted";
    } catch (const SettingsError& e) {
        EXPECT_NE(std::string(e.what()).find("'enabeld'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'terrain'"), std::string::npos) << e.what();
    }
    try {
        editSettings(panel, "terrian", {"enabled"});
        ADD_FAILURE() << "a misspelt section was accepted";
    } catch (const SettingsError& e) {
        EXPECT_NE(std::string(e.what()).find("'terrian'"), std::string::npos) << e.what();
    }
    ImGui::End();
    ImGui::EndFrame();
}

}  // namespace
}  // namespace firmament
