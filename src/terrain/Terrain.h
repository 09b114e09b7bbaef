#pragma once
// The terrain technique (docs/terrain.md): owns the height field (CPU and GPU), the clipmap's
// index buffer and its per-level constants, and draws the levels around the camera into the HDR
// frame with depth (lit by the atmosphere's tables and the shadow cascades), or their depth
// alone into a shadow cascade.
#include "frame/CloudShadowInputs.h"
#include "frame/FrameContext.h"
#include "frame/GroundLighting.h"
#include "frame/ShadowInputs.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/ShaderLibrary.h"
#include "gpu/Texture.h"
#include "terrain/ClipmapLayout.h"
#include "terrain/ClipmapMesh.h"
#include "terrain/HeightField.h"
#include "terrain/TerrainSettings.h"
#include "terrain/TerrainStructures.h"

#include <glm/glm.hpp>

namespace firmament {

class Terrain {
public:
    Terrain(ID3D11Device* device, HeightField field, double earthRadius);

    const HeightField& heightField() const { return field_; }
    ID3D11ShaderResourceView* heightFieldView() const { return heights_.srv.Get(); }  // R32_FLOAT, mip-mapped
    // Height above the sea-level sphere of the finest surface at (x, z).
    double groundHeight(double x, double z) const;
    // World y of that surface: the height less the Earth's drop.
    double groundY(double x, double z) const;
    // Lowest and highest surface altitude (the shadow cascades' depth range).
    double minAltitude() const { return field_.minHeight() - 2.0; }
    double maxAltitude() const { return field_.maxHeight() + 2.0; }

    // Places the levels around the camera for this frame (the shadow and main passes share them).
    void place(glm::dvec3 camera);
    const std::vector<ClipmapLevel>& levels() const { return levels_; }

    // The lit surface into the frame's HDR target, testing and writing its depth, over the
    // columns `lighting` covers.
    // The sun's light is shadowed by the cascades and by the clouds' shadow map.
    void render(FrameContext& frame, const GroundLighting& lighting, const ShadowInputs& shadows, const CloudShadowInputs& clouds,
                const TerrainSettings& settings);
    // Depth alone into the bound depth target, through `caster` (ShadowCasterConstants at b5).
    void renderDepth(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11Buffer* caster);

private:
    void drawLevels(ID3D11DeviceContext* context, unsigned view);
    void bindFieldTextures(ID3D11DeviceContext* context, bool pixelStage);

    HeightField field_;
    double earthRadius_;
    Texture2D heights_;  // R32_FLOAT, mip-mapped
    Texture2D slopes_;   // R32G32_FLOAT (dh/dx, dh/dz), mip-mapped
    Texture2D slopeMoments_;  // R32_FLOAT E[|s|^2], mip-mapped (HeightField::slopeSecondMoments)
    ClipmapMesh mesh_;
    ConstantBuffer<gpu::TerrainConstants> constants_;
    ComPtr<ID3D11SamplerState> linearClamp_, linearWrap_;
    ComPtr<ID3D11RasterizerState> solid_;  // back faces culled, scissored to the lighting's columns
    ComPtr<ID3D11DepthStencilState> depthTest_;
    std::vector<ClipmapLevel> levels_;
};

}  // namespace firmament
