#pragma once
// Light shafts by epipolar sampling (Yusov 2013, "Epipolar sampling"; Yusov's GPU Pro 5
// chapter; docs/lightshafts.md): the in-scattering is ray marched at a few samples along slices
// that run from the epipole (the sun's projection) to the screen's border, interpolated along
// the slices, and unwarped to the screen with bilateral weights. The passes, each timed:
//   1 camera-space depth, 2 slice end points, 3 sample coordinates, 4 coarse in-scattering,
//   5 refinement, 6 marking (a work list), 7 the slices' lines in the shadow maps, 8 their 1D
//   min/max trees, 9 ray marching of the listed samples (the brute-force reference's march,
//   walking the trees), 10 interpolation, 11 unwarping, 12 correction at depth breaks, and
//   "show sampling".
// The technique owns its epipolar-space textures and its two work lists; the shaders are in
// shaders/lightshafts/ (the passes' files are named after them).
#include "frame/CloudShadowInputs.h"
#include "frame/FrameContext.h"
#include "frame/ScatteringLookup.h"
#include "frame/ShadowInputs.h"
#include "frame/ShadowStructures.h"
#include "gpu/Buffers.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "gpu/Texture.h"
#include "gpu/WorkList.h"
#include "lightshafts/LightShaftSettings.h"
#include "lightshafts/LightShaftStructures.h"

#include <array>
#include <memory>

namespace firmament {

class EpipolarSampling {
public:
    explicit EpipolarSampling(ID3D11Device* device);

    // Draws the sky and the aerial perspective with shafts into the frame's HDR target.
    // `lightShaftConstants` and `shadowConstants` are the march's (LightShafts::constants);
    // `clouds` the clouds' transparency map and its constants (none without constants).
    void render(FrameContext& frame, const LightShaftSettings& settings, const ScatteringLookup& lookup, const ShadowInputs& shadows,
                ID3D11Buffer* lightShaftConstants, ID3D11Buffer* shadowConstants, const CloudShadowInputs& clouds = {});

    // The epipolar passes' constants for these settings, this view (the frame's constants
    // hold the camera and the sun), the camera's forward axis and the cascades (the trees are
    // walked when they are on and there is a cascade to march through).
    static gpu::EpipolarConstants constants(const LightShaftSettings& settings, const gpu::FrameConstants& frame, glm::vec3 cameraForward,
                                            const ShadowInputs& shadows = {});
    // The sun's projection in NDC (the anti-epipole's when the sun is behind the camera, then
    // `behind` is set), at most 100 from the centre.
    static glm::vec2 epipole(const glm::mat4& viewProjection, glm::vec3 directionToSun, bool& behind);

    // Epipolar-space results of the last render, for tests: slices x 1 end points; samples x
    // slices coordinates (xy NDC, z camera-space depth, w depth), interpolation sources, coarse
    // and interpolated in-scattering.
    const Texture2D& sliceEnds() const { return sliceEnds_; }
    const Texture2D& sampleCoordinates() const { return samples_; }
    const Texture2D& interpolationSources() const { return sources_; }
    const Texture2D& coarseInscattering() const { return coarse_; }
    const Texture2D& interpolatedInscattering() const { return interpolated_; }
    // The work list of the last render's ray-marching samples.
    const WorkList& marchList() const { return *marchList_; }
    // The slices' lines in the cascades (slices x 8: origin u, v and step u, v) and the trees
    // (2E x slices * marched cascades, lightshafts/minmax_trees.hlsli); empty before the first
    // frame that walks them.
    const Texture2D& sliceLines() const { return sliceLines_; }
    const Texture2D& minMaxTrees() const { return trees_; }

private:
    // Slots of the passes' shared inputs (shaders/lightshafts/epipolar_inputs.hlsli).
    enum Input { SceneRadiance, SceneDepth, NetDensity, SingleTable, HighOrderTable, MultipleTable, ShadowMap, CameraDepth, SliceEnds,
                 Samples, Coarse, Extinction, Sources, Marched, Interpolated, List, ListArguments, SliceLines, Trees, CascadeParts, CloudShadowMap,
                 InputCount };
    using Inputs = std::array<ID3D11ShaderResourceView*, InputCount>;

    void resize(ID3D11Device* device, int slices, int samples, int width, int height);
    // The trees' texture for `rows` trees of `entries` leaves in `format`.
    void resizeTrees(ID3D11Device* device, int entries, int rows, MinMaxFormat format);
    // Passes 7 and 8: true when the trees were built (the shadows drawn, a cascade to march).
    bool buildTrees(FrameContext& frame, const LightShaftSettings& settings, const ShadowInputs& shadows);
    // Binds the inputs, less `written` (the pass's outputs, which the pass binds as UAVs), runs
    // the compute shader over `groups` or over `list`, and unbinds.
    void run(FrameContext& frame, const ShaderKey& shader, std::initializer_list<ID3D11UnorderedAccessView*> outputs,
             std::initializer_list<Input> written, unsigned groupsX, unsigned groupsY, const WorkList* list = nullptr, bool layered = false);
    // Pass 9: the listed samples marched through the cascades, in one pass or cascade by cascade.
    void march(FrameContext& frame, CascadeProcessing mode, int marchedCascades);
    void prepareArguments(FrameContext& frame, const WorkList& list);
    void showSampling(FrameContext& frame, int slices, int samples);

    ConstantBuffer<gpu::EpipolarConstants> constants_;
    ConstantBuffer<gpu::CascadePassConstants> cascadePass_;
    ConstantBuffer<gpu::CloudShadowConstants> noClouds_;  // bound without the clouds' map: up.w == 0
    // Each listed sample's march through each cascade, in the cascade-by-cascade modes.
    StructuredBuffer cascadeParts_;
    unsigned cascadePartCount_ = 0;
    FullscreenPass states_;  // the fixed-function states of the sampling's dots
    Inputs inputs_{};
    ID3D11Buffer* constantBuffers_[7] = {};
    Texture2D cameraDepth_, sliceEnds_, samples_, coarse_, extinction_, sources_, marched_, interpolated_, sliceLines_, trees_;
    MinMaxFormat treeFormat_ = MinMaxFormat::Unorm16;
    std::unique_ptr<WorkList> marchList_, breakList_;
    int slices_ = 0, samplesPerSlice_ = 0, width_ = 0, height_ = 0;
};

}  // namespace firmament
