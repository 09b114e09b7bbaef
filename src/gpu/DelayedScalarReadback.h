#pragma once
// Reads a few texels of a 2D texture back to the CPU a few frames late, without ever waiting for
// the GPU: each frame's texels are copied into one of a ring of staging textures, and poll()
// maps only copies that have finished. For numbers the GUI shows (the adapted luminance) and that
// the program adapts to (the clouds' fragment counts).
#include <d3d11.h>
#include <wrl/client.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace firmament {

class DelayedScalarReadback {
public:
    // `count` texels of a 32-bit `format` (R32_FLOAT, R32_UINT) in a row.
    explicit DelayedScalarReadback(ID3D11Device* device, DXGI_FORMAT format = DXGI_FORMAT_R32_FLOAT, unsigned count = 1);

    // The texels (x .. x + count - 1, y) of `source`, a texture of the same format.
    void copy(ID3D11DeviceContext* context, ID3D11Texture2D* source, unsigned x = 0, unsigned y = 0);
    // The newest texels' bits whose copy has finished, if any has since the last call.
    std::optional<std::vector<std::uint32_t>> pollBits(ID3D11DeviceContext* context);
    // The same for one R32_FLOAT texel.
    std::optional<float> poll(ID3D11DeviceContext* context);

private:
    static constexpr size_t kSlots = 4;
    unsigned count_;
    std::array<Microsoft::WRL::ComPtr<ID3D11Texture2D>, kSlots> staging_;
    std::array<bool, kSlots> pending_{};
    size_t next_ = 0;    // slot the next copy goes to
    size_t oldest_ = 0;  // oldest slot that may be pending
};

}  // namespace firmament
