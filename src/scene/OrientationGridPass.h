#pragma once
// Draws the orientation grid (shaders/scene/orientation_grid.hlsl) into the HDR frame: a
// ground plane with 100 m and 1 km lines under a sky gradient and a sun disc, so the camera
// and the sun can be flown and checked before the terrain exists. Under light scattering it
// draws the ground alone, with depth, and the atmosphere draws the rest.
#include "core/Settings.h"
#include "gpu/FullscreenPass.h"
#include "gpu/ShaderLibrary.h"

#include <d3d11.h>

namespace firmament {

struct SceneSettings {
    bool orientationGrid = true;

    void visit(SettingsVisitor& v) { v.field("orientationGrid", orientationGrid, "Orientation grid"); }  // section "scene"
};

class OrientationGridPass {
public:
    explicit OrientationGridPass(ID3D11Device* device);

    // `frameConstants`: the FrameConstants buffer (b0). Sky, ground and haze of its own.
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11Buffer* frameConstants,
                ID3D11RenderTargetView* hdrFrame, int width, int height);
    // The ground alone, writing its depth, for the atmosphere to draw the sky and the haze.
    void renderGround(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11Buffer* frameConstants,
                      ID3D11RenderTargetView* hdrFrame, ID3D11DepthStencilView* depth, int width, int height);

private:
    FullscreenPass fullscreen_;
    ComPtr<ID3D11DepthStencilState> writeDepth_;
};

}  // namespace firmament
