#pragma once
// The clouds' path-traced reference on the GPU (Reference (path traced); docs/clouds.md,
// "Path-traced reference"): the medium the particles describe, traced by Monte Carlo paths
// through every bounce, accumulated over frames while nothing changes, and blended over the frame
// in place of the particles' shading. Its parts:
//  1. the index (clouds/reference_index.hlsl): each ring's cells list the particles generated in
//     them, and hold a majorant of the extinction that can reach them per slab of height;
//  2. the paths (clouds/trace_clouds.hlsl): a thread per pixel adds paths to the accumulation;
//  3. their mean over the frame (clouds/reference_composite.hlsl).
// The CPU twin is CloudPathTracer (src/reference/CloudPathTracer.h) over a ParticleMedium.
#include "clouds/CloudSettings.h"
#include "clouds/CloudStructures.h"
#include "gpu/Buffers.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/Texture.h"

#include <d3d11.h>

#include <cstdint>
#include <string>

namespace firmament {

// The define that picks the atmosphere model the clouds' shaders read (clouds/cloud_atmosphere.hlsli):
// CLOUD_ATMOSPHERE=1 Yusov 2013, 2 Bruneton and Neyret 2008, 3 Hillaire 2020.
std::string cloudAtmosphereDefine(int atmosphere);

class CloudParticles;
struct FrameContext;

// The ground under the clouds, for the reference's paths: the terrain's flat meadow at its mean
// (shaders/terrain/material.hlsli, between meadow and dry grass).
inline constexpr float kReferenceGroundAlbedo[3] = {0.12f, 0.13f, 0.06f};
// A path's events are bounded only against a bug: far beyond any cloud's.
inline constexpr unsigned kReferenceEventLimit = 100000;

class CloudReference {
public:
    explicit CloudReference(ID3D11Device* device);

    // This frame's index of `particles` (updated this frame).
    void buildIndex(FrameContext& frame, CloudParticles& particles, const CloudSettings& settings);
    // Binds the index for a shader that walks the medium (clouds/reference_medium.hlsli): the
    // particles at t1, the tables at t10..t12, the constants at b3 (compute stage).
    void bindMedium(ID3D11DeviceContext* context, CloudParticles& particles) const;
    // The constants of the next pass: the tests fill them for their own kernel.
    void setConstants(ID3D11DeviceContext* context, const gpu::CloudReferenceConstants& constants);

    // Adds settings.referencePaths paths per pixel to the accumulation, at one pixel of every
    // settings.referenceStride^2 block in turn (starting over when `key`, a digest of everything
    // the picture depends on, or either setting changed), then blends their mean over
    // the frame's HDR target. The caller binds the atmosphere's constants at b2 and b4, its
    // tables at t5..t9 and its sampler at s1 (compute stage); `atmosphere` (CLOUD_ATMOSPHERE) picks
    // the shader.
    void trace(FrameContext& frame, CloudParticles& particles, const CloudSettings& settings, std::uint64_t key, int atmosphere, glm::uvec4 modes);
    // Paths in the accumulation after the last trace() at the pixels with the fewest.
    unsigned pathsPerPixel() const;
    // Passes since the accumulation started over, and the pixel stride they ran at.
    unsigned passes() const { return passes_; }
    unsigned stride() const { return stride_; }
    // Paths the last trace() started: its pixels times the paths per pixel per frame (the
    // benchmark's "cloud reference paths", the time per path's divisor).
    unsigned pathsLastPass() const { return pathsLastPass_; }

    ID3D11Texture2D* cellCounts() const { return counts_.texture.Get(); }

private:
    void resize(ID3D11Device* device, const CloudSettings& settings);

    ConstantBuffer<gpu::CloudReferenceConstants> constants_;
    ComPtr<ID3D11BlendState> premultiplied_;
    int tableWidth_ = 0, tableHeight_ = 0, layers_ = 0;
    Texture2D counts_;     // R32_UINT: particles per cell
    StructuredBuffer slots_;  // uint: `layers` per cell
    StructuredBuffer majorants_;  // float per cell and slab of height (2 per layer; 1/m)
    Texture2D accumulation_;  // R32G32B32A32_FLOAT: the paths' light, and how many reached the scene
    unsigned passes_ = 0;  // since the accumulation started over
    unsigned added_ = 1, stride_ = 1;
    unsigned pathsLastPass_ = 0;
    std::uint64_t key_ = 0;
};

}  // namespace firmament
