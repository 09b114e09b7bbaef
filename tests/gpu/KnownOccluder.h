#pragma once
// The shadow tests' known occluder: a horizontal square hovering over flat ground, drawn into
// the cascades by tests/shaders/shadows/shadow_probe.hlsl (occluder_vs). ShadowTest checks the
// cascades' visibility against it, LightShaftMarchTest the light shafts' march.
#include "gpu/ConstantBuffer.h"
#include "gpu/ShaderLibrary.h"
#include "shadows/CascadedShadowMaps.h"

namespace firmament::test {

inline constexpr glm::vec4 kSquare(-40.0f, 120.0f, 60.0f, 260.0f);  // x min, z min, x max, z max
inline constexpr float kSquareHeight = 45.0f;                       // y of the square

struct OccluderConstants {
    glm::vec4 square;  // kSquare
    glm::vec4 height;  // x: kSquareHeight
};

// Draws the square into every cascade of `shadows` (after their update()).
inline void drawKnownOccluder(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& testShaders, CascadedShadowMaps& shadows) {
    ConstantBuffer<OccluderConstants> occluder(device);
    occluder.update(context, OccluderConstants{kSquare, glm::vec4(kSquareHeight)});
    shadows.render(context, [&](ID3D11Buffer* caster) {
        context->VSSetConstantBuffers(5, 1, &caster);
        context->VSSetConstantBuffers(1, 1, occluder.address());
        context->VSSetShader(testShaders.vertexShader({"shadows/shadow_probe.hlsl", "occluder_vs", "vs_5_0", {}}), nullptr, 0);
        context->PSSetShader(nullptr, nullptr, 0);
        context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        context->IASetInputLayout(nullptr);
        context->Draw(6, 0);
    });
}

}  // namespace firmament::test
