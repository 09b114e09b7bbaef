#pragma once
// The cascaded shadow maps technique (docs/shadows.md): owns the depth atlas (one square tile
// per cascade, four to a row), the comparison sampler and the constants the readers bind; fits the
// cascades to the camera each frame (CascadeSplits.h) and has the casters draw their depth into
// each. The cascades and their matrices stay readable (cascades()) for the light shafts.
#include "core/Camera.h"
#include "frame/ShadowInputs.h"
#include "frame/ShadowStructures.h"
#include "gpu/ConstantBuffer.h"
#include "gpu/Texture.h"
#include "shadows/CascadeSplits.h"
#include "shadows/ShadowSettings.h"

#include <d3d11.h>
#include <wrl/client.h>

#include <functional>
#include <vector>

namespace firmament {

inline constexpr int kAtlasColumns = 4;

class CascadedShadowMaps {
public:
    explicit CascadedShadowMaps(ID3D11Device* device);

    // Fits the cascades to the camera and the sun (double precision), and writes the constants.
    // casterReach: metres towards the sun beyond each cascade's sphere that casters may stand.
    // cascadeAroundCamera: the cascade whose map must also hold the camera's place and the
    // frustum before its split (the light shafts' first marched cascade; -1 for none).
    void update(ID3D11DeviceContext* context, const Camera& camera, double aspectRatio, glm::dvec3 directionToSun,
                const ShadowSettings& settings, double casterReach, int cascadeAroundCamera = -1);
    // Clears the atlas and calls drawCasters for each cascade with its ShadowCasterConstants
    // buffer, the atlas bound as the depth target, the cascade's tile as the viewport, and a
    // biased, unculled rasterizer state.
    void render(ID3D11DeviceContext* context, const std::function<void(ID3D11Buffer* caster)>& drawCasters);
    // Draws more casters into the cascades drawn this frame, without clearing them, in the same
    // state; drawCasters also gets the cascade's index (its Cascade in cascades()).
    void addCasters(ID3D11DeviceContext* context, const std::function<void(ID3D11Buffer* caster, size_t cascade)>& drawCasters);

    ShadowInputs inputs() const;  // no shadows (mode.x == 0) until update() ran with shadows on
    const std::vector<Cascade>& cascades() const { return cascades_; }
    const gpu::ShadowConstants& constants() const { return constants_; }
    int resolution() const { return resolution_; }

private:
    void createMap(int resolution, int cascades);
    void drawCascades(ID3D11DeviceContext* context, bool clear, const std::function<void(ID3D11Buffer* caster, size_t cascade)>& drawCasters);

    ID3D11Device* device_;
    ComPtr<ID3D11Texture2D> map_;
    ComPtr<ID3D11DepthStencilView> dsv_;
    ComPtr<ID3D11ShaderResourceView> srv_;
    ComPtr<ID3D11SamplerState> comparison_;
    ComPtr<ID3D11RasterizerState> casterRaster_;
    ComPtr<ID3D11DepthStencilState> casterDepth_;
    ConstantBuffer<gpu::ShadowConstants> constantBuffer_;
    ConstantBuffer<gpu::ShadowCasterConstants> casterBuffer_;
    gpu::ShadowConstants constants_{};
    std::vector<Cascade> cascades_;
    int resolution_ = 0;  // of one cascade
    int cascadeCount_ = 0;
    int columns_ = 1, rows_ = 1;  // of the atlas's tiles
};

}  // namespace firmament
