#pragma once
// Each cloud particle's column along the sun: the optical depth of the particles nearer the sun,
// and of those beyond it (Yusov 2014, "Computing light occlusion", which finds the first; deck
// diffusion needs both), and of each the part in the particle's deck, unbroken by clear air
// (docs/clouds.md, "Light occlusion" and "Deck diffusion"), on the GPU each frame:
//  1. tiling: the particles rasterized from the sun into the light-space grid
//     (clouds/tile_particles.hlsl), each appended to the list of every tile its footprint covers;
//  2. the lists ordered from the sun, each in place (clouds/order_tiles.hlsl);
//  3. opacity: a thread per particle (DispatchIndirect) walks the list of its tile from the sun,
//     past itself to the end or, with the early exit, until the column is kOpacityEarlyExitDepth
//     thick (clouds/particle_opacity.hlsl).
// The shading lights the particle by the direct sun through the column above and by deck
// diffusion through its deck. The CPU twin is src/reference/SunColumnTwin.
#include "clouds/CloudSettings.h"
#include "clouds/CloudStructures.h"
#include "gpu/Buffers.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/LinkedLists.h"
#include "gpu/Texture.h"

#include <d3d11.h>

namespace firmament {

class CloudParticles;
struct FrameContext;
struct ParticleTables;

class ParticleOpacity {
public:
    explicit ParticleOpacity(ID3D11Device* device);

    // The node pool starts with room for this many tiles per particle of the grid's capacity at a
    // 512 map (four times as many per doubling), and grows like the fragment lists' (a few frames
    // after a frame asked for more, or at once when the first lists built into it did not fit),
    // up to kMaxPoolBytes.
    static constexpr unsigned kNodesPerParticle = 16;
    static constexpr size_t kMaxPoolBytes = size_t{512} << 20;

    // This frame's particles (`particles` updated) tiled from the sun and their columns found.
    void compute(FrameContext& frame, CloudParticles& particles, const ParticleTables& tables, const CloudSettings& settings);
    // Light occlusion off: every particle's column empty (the sun unoccluded, no deck around it).
    void clear(ID3D11Device* device, ID3D11DeviceContext* context, unsigned particleCapacity);
    // The particles' columns, by slot (StructuredBuffer<float4>: the optical depths above and beyond,
    // then their parts in the particle's deck).
    ID3D11ShaderResourceView* sunColumn() const { return column_.srv.Get(); }
    ID3D11Buffer* sunColumnBuffer() const { return column_.buffer.Get(); }
    const gpu::CloudLightSpaceConstants& constants() const { return constants_; }
    unsigned nodeCapacity() const { return tiles_.capacity(); }
    // Whether the last frame computed the transmittance (not cleared it).
    bool computed() const { return computed_; }

    // The last frame's tile nodes asked for, and those past the pool. Waits for the GPU (tests,
    // benchmark).
    struct Counts {
        unsigned nodes = 0;
        unsigned nodesDropped = 0;
    };
    Counts readCounts(ID3D11Device* device, ID3D11DeviceContext* context) const;

private:
    void resize(ID3D11Device* device, unsigned particleCapacity, int resolution);
    void buildTiles(FrameContext& frame, CloudParticles& particles, const CloudSettings& settings);

    ConstantBuffer<gpu::CloudLightSpaceConstants> constantsBuffer_;
    gpu::CloudLightSpaceConstants constants_{};
    ComPtr<ID3D11BlendState> noColourWrites_;
    ComPtr<ID3D11RasterizerState> noCulling_;
    ComPtr<ID3D11SamplerState> linearWrap_;
    int resolution_ = 0;
    bool computed_ = false;
    unsigned particleCapacity_ = 0;
    GpuLinkedLists tiles_;    // uint3 nodes: the particle's slot, the next node, asuint(distance toward the sun)
    Texture2D rasterTarget_;  // R8_UNORM, never written: the map's size for the tiling's draw
    StructuredBuffer column_;  // float2 per slot
};

}  // namespace firmament
