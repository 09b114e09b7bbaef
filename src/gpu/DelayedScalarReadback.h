#pragma once
// Reads a 1 x 1 R32_FLOAT texture back to the CPU a few frames late, without ever waiting for
// the GPU: each frame's value is copied into one of a ring of staging textures, and poll()
// maps only copies that have finished. For numbers the GUI shows (the adapted luminance).
#include <d3d11.h>
#include <wrl/client.h>

#include <array>
#include <optional>

namespace firmament {

class DelayedScalarReadback {
public:
    explicit DelayedScalarReadback(ID3D11Device* device);

    void copy(ID3D11DeviceContext* context, ID3D11Texture2D* source);  // a 1 x 1 R32_FLOAT texture
    // The newest value whose copy has finished, if any has since the last call.
    std::optional<float> poll(ID3D11DeviceContext* context);

private:
    static constexpr size_t kSlots = 4;
    std::array<Microsoft::WRL::ComPtr<ID3D11Texture2D>, kSlots> staging_;
    std::array<bool, kSlots> pending_{};
    size_t next_ = 0;    // slot the next copy goes to
    size_t oldest_ = 0;  // oldest slot that may be pending
};

}  // namespace firmament
