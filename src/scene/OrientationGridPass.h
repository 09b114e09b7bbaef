#pragma once
// Draws the orientation grid (shaders/scene/orientation_grid.hlsl) into the HDR frame: a
// ground plane with 100 m and 1 km lines under a sky gradient and a sun disc, so the camera
// and the sun can be flown and checked before the atmosphere and terrain exist.
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

    // `frameConstants`: the FrameConstants buffer (b0).
    void render(ID3D11DeviceContext* context, ShaderLibrary& shaders, ID3D11Buffer* frameConstants,
                ID3D11RenderTargetView* hdrFrame, int width, int height);

private:
    FullscreenPass fullscreen_;
};

}  // namespace firmament
