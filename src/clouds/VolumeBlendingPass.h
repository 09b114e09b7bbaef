#pragma once
// Volume-aware blending of the clouds' particles on the GPU (Yusov 2014; docs/clouds.md,
// "Blending"), through either pixel-ordering path of src/clouds/ParticleBlending.h, with the
// resources each path needs at the clouds' resolution:
//  - per-pixel lists: a head texture (R32_UINT) with a row of counters, a pool of nodes; the particles' pixel
//    shader appends (shaders/clouds/fragment_lists.hlsli), the resolve sorts and blends
//    (resolve_fragments.hlsl);
//  - rasterizer-ordered views: the stored fragment's colour and extinction (RGBA32F) and extent
//    (RG32F); the particles' pixel shader merges in primitive order and sends what is pushed behind
//    to the target; the resolve blends the stored one.
#include "clouds/CloudStructures.h"
#include "clouds/ParticleBlending.h"
#include "gpu/Buffers.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/LinkedLists.h"
#include "gpu/Texture.h"

#include <d3d11.h>

#include <glm/vec4.hpp>

#include <optional>


namespace firmament {

class ShaderLibrary;

BlendingSupport queryBlendingSupport(ID3D11Device* device);

class VolumeBlendingPass {
public:
    explicit VolumeBlendingPass(ID3D11Device* device);

    // The lists' pool starts with room for a pixel's whole resolve limit (gpu::kMaxPixelFragments) in every
    // pixel, up to kInitialPoolBytes. When a frame asks for more, the pool grows a few frames
    // later to 5/4 of what was asked, up to kMaxPoolBytes; what does not fit is dropped (the
    // last particles drawn, the nearest) and counted. The first lists of a new pool (at start, at
    // a new size) are checked at once instead: see firstBuildOverflowed.
    static constexpr unsigned kNodesPerPixel = gpu::kMaxPixelFragments;
    static constexpr size_t kInitialPoolBytes = size_t{128} << 20;
    static constexpr size_t kMaxPoolBytes = size_t{512} << 20;

    // Sizes the path's resources for a width x height target and clears them (Alpha: nothing).
    void begin(ID3D11Device* device, ID3D11DeviceContext* context, ParticleBlending path, int width, int height);
    // Binds the target, its blending (premultiplied alpha; no colour writes for the lists) and the
    // views the particles' pixel shader writes, from u1.
    // `blend`: the layers' blending (nullptr: premultiplied alpha that keeps the target's alpha).
    void bindForParticles(ID3D11DeviceContext* context, ID3D11RenderTargetView* target, ID3D11BlendState* blend = nullptr) const;
    // The lists' views at u1 and u2 of the compute stage (tests append synthetic fragments).
    void bindListsForCompute(ID3D11DeviceContext* context) const;
    // After the particles were drawn: true, once, when these were the first per-pixel lists of a
    // new pool and they did not fit; the pool has grown (the GPU was waited for) and the caller
    // begins and draws again. False for the other paths.
    bool firstBuildOverflowed(ID3D11Device* device, ID3D11DeviceContext* context) {
        return path_ == ParticleBlending::PerPixelLists && lists_.firstBuildOverflowed(device, context);
    }
    // Blends what the particles left over `target` (premultiplied alpha), and unbinds the views.
    void resolve(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11RenderTargetView* target, ID3D11BlendState* blend = nullptr);

    ParticleBlending path() const { return path_; }
    unsigned nodeCapacity() const { return path_ == ParticleBlending::PerPixelLists ? lists_.capacity() : 0u; }
    // The GPU memory the path holds: the lists' heads and pool, or the ordered path's RGBA32F and
    // RG32F per-pixel stores (Alpha: none).
    size_t memoryBytes() const;

    // What did not fit: nodes asked of the pool past its capacity, fragments past one pixel's
    // resolve limit (kMaxPixelFragments in cloud_structures.hlsli).
    struct Overflow {
        unsigned nodesAskedFor = 0;
        unsigned nodesDropped = 0;
        unsigned fragmentsDropped = 0;
    };
    // Waits for the GPU (tests, benchmark).
    Overflow readOverflow(ID3D11Device* device, ID3D11DeviceContext* context) const;
    // A few frames late, never waiting (the GUI); nothing before the first copy has finished.
    std::optional<Overflow> latestOverflow() const;

private:

    ParticleBlending path_ = ParticleBlending::Alpha;
    int width_ = 0, height_ = 0;
    GpuLinkedLists lists_;        // FragmentNode; the second counter: fragments past a pixel's limit
    ConstantBuffer<glm::uvec4> resolveConstants_;  // x: the counters' row
    Texture2D storedColour_;      // ordered: RGBA32F colour, extinction
    Texture2D storedExtent_;      // ordered: RG32F front, back (back <= front: none stored)
    ComPtr<ID3D11BlendState> premultiplied_;
    ComPtr<ID3D11BlendState> noColourWrites_;
    ComPtr<ID3D11RasterizerState> noCulling_;
    ComPtr<ID3D11DepthStencilState> noDepth_;
};

}  // namespace firmament
