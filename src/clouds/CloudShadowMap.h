#pragma once
// The clouds' shadows (Yusov 2014, "Integration with light scattering"; docs/clouds.md,
// "Shadows and shafts from clouds"): the particles drawn from the sun into light-space maps of
// their transparency and the stretch of each sun ray they occupy (clouds/cloud_shadow_map.hlsl),
// orthographic squares centred over the camera: a near map of fine texels for the shadows around
// it, and a far one over the whole particle field, two slices of one texture array. The terrain
// and the light shafts read them (shadows/cloud_shadow.hlsli); for "Shafts from clouds: shadow
// map" they are drawn into the shadow cascades as casters instead (drawIntoCascade).
#include "clouds/CloudSettings.h"
#include "clouds/CloudStructures.h"
#include "frame/CloudShadowInputs.h"
#include "frame/ShadowStructures.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/Texture.h"

#include <glm/vec3.hpp>

#include <d3d11.h>

namespace firmament {

class CloudParticles;
struct FrameContext;
struct ParticleTables;

class CloudShadowMap {
public:
    // Texels along a side of each map, and the near map's half-width (m): 39 m texels over 40 km.
    static constexpr int kResolution = 1024;
    static constexpr double kHalfWidth = 2.0e4;
    // Each map gives way (the near to the far, the far to no shadow) over this share of its
    // half-width at its edge.
    static constexpr double kEdgeFade = 0.1;

    explicit CloudShadowMap(ID3D11Device* device);

    // The maps for a camera at `camera` and the sun along `toSun` (unit): centred over the camera,
    // each centre snapped to whole texels of its map across the sun so that the shadows stay put
    // as the camera moves; the far map `farHalfWidth` wide. `active` sets up.w (whether readers
    // apply them).
    static gpu::CloudShadowConstants constants(glm::dvec3 camera, glm::dvec3 toSun, bool active, double farHalfWidth, int resolution = kResolution,
                                               double halfWidth = kHalfWidth);
    // The far map's half-width for `settings`: the particle field's, as the light-space grid's.
    static double farHalfWidth(const CloudSettings& settings);

    // This frame's particles (updated) drawn into both maps; readers then apply them.
    void render(FrameContext& frame, CloudParticles& particles, const ParticleTables& tables, const CloudSettings& settings);
    // No clouds this frame: readers apply nothing.
    void clear(ID3D11DeviceContext* context);
    // Whether the last frame drew the map.
    bool active() const { return constants_.up.w != 0.0f; }
    CloudShadowInputs inputs() const { return {constantsBuffer_.get(), srv_.Get()}; }
    const gpu::CloudShadowConstants& constants() const { return constants_; }
    ID3D11ShaderResourceView* mapView() const { return srv_.Get(); }  // Texture2DArray: slice 0 near, 1 far

    // "Shafts from clouds: shadow map": where the clouds let through less than half of the sun's
    // light, the middle of their stretch drawn as a caster into the shadow cascade bound for
    // depth, whose projection is `cascadeWorldToClip` (the renderer calls it once per cascade).
    void drawIntoCascade(FrameContext& frame, const glm::dmat4& cascadeWorldToClip);

private:
    ConstantBuffer<gpu::CloudShadowConstants> constantsBuffer_;
    ConstantBuffer<gpu::CloudShadowConstants> writerBuffer_;  // a map's own: its centre as the near one's
    ConstantBuffer<gpu::CloudShadowMergeConstants> mergeBuffer_;
    gpu::CloudShadowConstants constants_{};
    // R32G32B32A32_FLOAT, two slices: (far, -near, 0, transmittance) per texel.
    ComPtr<ID3D11Texture2D> maps_;
    ComPtr<ID3D11RenderTargetView> slices_[2];
    ComPtr<ID3D11ShaderResourceView> srv_;
    ComPtr<ID3D11BlendState> blend_;
    ComPtr<ID3D11RasterizerState> noCulling_;
    ComPtr<ID3D11SamplerState> linearWrap_;
};

}  // namespace firmament
