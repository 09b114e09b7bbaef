#pragma once
// The light shafts technique (docs/lightshafts.md): the light the atmosphere scatters into each
// view ray, counted only where the sun reaches, with the sun's visibility read from the
// cascaded shadow maps (Yusov 2013; Yusov's GPU Pro 5 chapter). It replaces the atmosphere's
// Sky and Aerial perspective passes when it is on, and reads Yusov's tables through the
// atmosphere's hand-off (ScatteringLookup) and the cascades through theirs (ShadowInputs).
// Two techniques ("Scattering technique"): epipolar sampling (EpipolarSampling), and the
// brute-force reference, one ray march per pixel ("Light shafts (brute force)").
#include "frame/CloudShadowInputs.h"
#include "frame/FrameContext.h"
#include "frame/ScatteringLookup.h"
#include "frame/ShadowInputs.h"
#include "frame/ShadowStructures.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/FullscreenPass.h"
#include "lightshafts/EpipolarSampling.h"
#include "lightshafts/LightShaftSettings.h"
#include "lightshafts/LightShaftStructures.h"

namespace firmament {

// Where the shafts end: beyond this distance from the camera the in-scattering is unshadowed
// (Yusov 2013's sample: 300 km).
inline constexpr float kLightShaftReach = 300.0e3f;

class LightShafts {
public:
    explicit LightShafts(ID3D11Device* device);

    // Draws the sky and the aerial perspective with shafts into the frame's HDR target. `clouds`:
    // the clouds' transparency map, sampled at every step of the march (none: no constants).
    void render(FrameContext& frame, const LightShaftSettings& settings, const ScatteringLookup& lookup, const ShadowInputs& shadows,
                const CloudShadowInputs& clouds = {});

    // The pass's constants for these settings and modes; `cascadeResolution` bounds the steps.
    static gpu::LightShaftConstants constants(const LightShaftSettings& settings, const ScatteringLookup& lookup, int cascadeResolution);

private:
    void renderBruteForce(FrameContext& frame, const ScatteringLookup& lookup, const ShadowInputs& shadows, ID3D11Buffer* shadowConstants,
                          const CloudShadowInputs& clouds);

    EpipolarSampling epipolar_;
    FullscreenPass fullscreen_;
    ConstantBuffer<gpu::LightShaftConstants> constants_;
    ConstantBuffer<gpu::ShadowConstants> noShadows_;  // bound when the cascades are off: mode.x == 0
    ConstantBuffer<gpu::CloudShadowConstants> noClouds_;  // the brute force's without the clouds' map: up.w == 0
};

}  // namespace firmament
