#pragma once
// Draws the orientation grid (shaders/scene/orientation_grid.hlsl) into the HDR frame: a
// ground plane with 100 m and 1 km lines under a sky gradient and a sun disc, so the camera
// and the sun can be flown and checked without the atmosphere and the terrain. Under light
// scattering it draws the ground alone, with depth, and the atmosphere draws the rest.
#include "frame/FrameContext.h"
#include "gpu/FullscreenPass.h"
#include "scene/SceneSettings.h"

namespace firmament {

class OrientationGridPass {
public:
    explicit OrientationGridPass(ID3D11Device* device);

    // `groundOnly`: the ground alone, writing its depth (the atmosphere draws the sky and the
    // haze); otherwise sky, ground and haze of its own.
    void render(FrameContext& frame, bool groundOnly);

private:
    FullscreenPass fullscreen_;
    ComPtr<ID3D11DepthStencilState> writeDepth_;
};

}  // namespace firmament
