#include "gpu/DelayedScalarReadback.h"

#include "gpu/Hresult.h"

#include <cstring>

namespace firmament {

DelayedScalarReadback::DelayedScalarReadback(ID3D11Device* device) {
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = desc.Height = 1;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R32_FLOAT;
    desc.SampleDesc.Count = 1;
    desc.Usage = D3D11_USAGE_STAGING;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    for (auto& texture : staging_) check(device->CreateTexture2D(&desc, nullptr, &texture), "CreateTexture2D (scalar read-back)");
}

void DelayedScalarReadback::copy(ID3D11DeviceContext* context, ID3D11Texture2D* source) {
    if (pending_[next_] && next_ == oldest_) oldest_ = (oldest_ + 1) % kSlots;  // the ring is full: the oldest is dropped
    context->CopyResource(staging_[next_].Get(), source);
    pending_[next_] = true;
    next_ = (next_ + 1) % kSlots;
}

std::optional<float> DelayedScalarReadback::poll(ID3D11DeviceContext* context) {
    std::optional<float> newest;
    while (pending_[oldest_]) {
        D3D11_MAPPED_SUBRESOURCE mapped{};
        if (context->Map(staging_[oldest_].Get(), 0, D3D11_MAP_READ, D3D11_MAP_FLAG_DO_NOT_WAIT, &mapped) != S_OK) break;
        float value = 0.0f;
        std::memcpy(&value, mapped.pData, sizeof(value));
        context->Unmap(staging_[oldest_].Get(), 0);
        newest = value;
        pending_[oldest_] = false;
        oldest_ = (oldest_ + 1) % kSlots;
    }
    return newest;
}

}  // namespace firmament
