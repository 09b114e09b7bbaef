#pragma once
// The clouds' particles, generated on the GPU each frame (Yusov 2014, "Particle generation";
// docs/clouds.md): the density map (when its resolution changes), the valid cells of the grid,
// a particle per layer of each valid cell through DispatchIndirect, and their back-to-front order
// by a GPU sort (bitonic blocks of 256, then merges), then, with "Visibility culling", the sorted
// list of those in the view (clouds/cull_particles.hlsl). Every pass after the valid cells runs
// from arguments the GPU wrote: DispatchIndirect, and DrawInstancedIndirect for the draws.
#include "clouds/CloudSettings.h"
#include "clouds/CloudStructures.h"
#include "gpu/Buffers.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/ShaderKey.h"
#include "gpu/Texture.h"
#include "gpu/WorkList.h"

#include <d3d11.h>
#include <wrl/client.h>

#include <memory>

namespace firmament {

using Microsoft::WRL::ComPtr;

struct FrameContext;

// Which particles a draw takes: every one (the passes seen from the sun), or those in the view.
enum class ParticleSet { All, InView };

class CloudParticles {
public:
    explicit CloudParticles(ID3D11Device* device);

    // This frame's particles, sorted back to front, for the camera and time of `frame`;
    // `tableSizes`: the optical depth table's N0..N3, for the passes that read it.
    void update(FrameContext& frame, const CloudSettings& settings, glm::vec4 tableSizes = glm::vec4(0.0f));
    // "Show particles": their bounding ellipsoids into the HDR target, with depth.
    void drawBoundingShapes(FrameContext& frame);
    // The particles of `set`, back to front, each as a quad over its ellipsoid with these shaders
    // (clouds/particle_shape.hlsli), into the targets and states the caller bound, over a viewport
    // of width x height (0: the frame's). InView is every particle when culling is off.
    void drawInstanced(FrameContext& frame, const ShaderKey& vertexShader, const ShaderKey& pixelShader, ParticleSet set, int width = 0, int height = 0);

    // What update() wrote (tests and the GUI read them back).
    const gpu::CloudFieldConstants& constants() const { return constants_; }
    unsigned capacity() const { return capacity_; }
    ID3D11Texture2D* densityMap() const { return densityMap_.texture.Get(); }
    ID3D11Buffer* cellList() const { return cells_.buffer.Get(); }
    const WorkList& validCells() const { return *validCells_; }
    ID3D11Buffer* particles() const { return particles_.buffer.Get(); }
    // The particles' count at [3] (beyond the capacity when the grid holds more), then the
    // dispatch's groups and the draw's arguments.
    ID3D11Buffer* particleArguments() const { return arguments_.buffer.Get(); }
    // (distance bits, slot) in back-to-front order, the first min(count, capacity) entries.
    ID3D11Buffer* sortedKeys() const { return keys_[sortedIndex_].buffer.Get(); }
    // With culling: the keys of the particles in the view, in the same order, their count at [3]
    // and the draw's arguments at [4..7] (as particleArguments()); null without.
    ID3D11Buffer* visibleKeys() const { return culled_ ? visibleKeys_.buffer.Get() : nullptr; }
    ID3D11Buffer* visibleArguments() const { return culled_ ? visibleArguments_.buffer.Get() : nullptr; }
    // Views and constants for the passes after this one (the particles' opacity).
    ID3D11ShaderResourceView* sortedKeysView() const { return keys_[sortedIndex_].srv.Get(); }
    ID3D11ShaderResourceView* particlesView() const { return particles_.srv.Get(); }
    ID3D11ShaderResourceView* argumentsView() const { return arguments_.srv.Get(); }
    ID3D11Buffer* fieldConstants() const { return fieldBuffer_.get(); }

private:
    void resizeGrid(ID3D11Device* device, const CloudSettings& settings);
    void generateDensityMap(FrameContext& frame, int resolution);
    void sort(FrameContext& frame);
    void cullToView(FrameContext& frame);

    ConstantBuffer<gpu::CloudFieldConstants> fieldBuffer_;
    ConstantBuffer<gpu::CloudSortConstants> sortBuffer_;
    gpu::CloudFieldConstants constants_{};
    ComPtr<ID3D11RasterizerState> noCulling_;
    ComPtr<ID3D11DepthStencilState> depth_;

    int rings_ = 0, dimension_ = 0, layers_ = 0, resolution_ = 0;
    unsigned capacity_ = 0;
    Texture2D densityMap_;
    StructuredBuffer cells_;  // packed ring, i, j of every cell (src/clouds/CloudGrid.h)
    std::unique_ptr<WorkList> validCells_;
    StructuredBuffer particles_, keys_[2];
    IndirectArguments arguments_;
    int sortedIndex_ = 0;
    StructuredBuffer visibleKeys_;
    IndirectArguments visibleArguments_;
    bool culled_ = false;
};

}  // namespace firmament
