#pragma once
// A constant buffer holding one shared structure (src/gpu/SharedStructures.h), updated
// whole each time it changes.
#include "gpu/Hresult.h"

#include <d3d11.h>
#include <wrl/client.h>

namespace firmament {

template <typename T>
class ConstantBuffer {
    static_assert(sizeof(T) % 16 == 0, "constant buffers are multiples of 16 bytes");

public:
    explicit ConstantBuffer(ID3D11Device* device) {
        D3D11_BUFFER_DESC desc{};
        desc.ByteWidth = sizeof(T);
        desc.Usage = D3D11_USAGE_DEFAULT;
        desc.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
        check(device->CreateBuffer(&desc, nullptr, &buffer_), "CreateBuffer (constant buffer)");
    }

    void update(ID3D11DeviceContext* context, const T& value) { context->UpdateSubresource(buffer_.Get(), 0, nullptr, &value, 0, 0); }
    ID3D11Buffer* get() const { return buffer_.Get(); }
    ID3D11Buffer* const* address() const { return buffer_.GetAddressOf(); }

private:
    Microsoft::WRL::ComPtr<ID3D11Buffer> buffer_;
};

}  // namespace firmament
