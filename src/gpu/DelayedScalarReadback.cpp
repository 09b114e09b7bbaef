#include "gpu/DelayedScalarReadback.h"

#include "gpu/Hresult.h"

#include <cstring>

namespace firmament {

DelayedScalarReadback::DelayedScalarReadback(ID3D11Device* device, DXGI_FORMAT format, unsigned count) : count_(count) {
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = count;
    desc.Height = 1;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = format;
    desc.SampleDesc.Count = 1;
    desc.Usage = D3D11_USAGE_STAGING;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    for (auto& texture : staging_) check(device->CreateTexture2D(&desc, nullptr, &texture), "CreateTexture2D (delayed read-back)");
}

void DelayedScalarReadback::copy(ID3D11DeviceContext* context, ID3D11Texture2D* source, unsigned x, unsigned y) {
    if (pending_[next_] && next_ == oldest_) oldest_ = (oldest_ + 1) % kSlots;  // the ring is full: the oldest is dropped
    const D3D11_BOX box{x, y, 0, x + count_, y + 1, 1};
    context->CopySubresourceRegion(staging_[next_].Get(), 0, 0, 0, 0, source, 0, &box);
    pending_[next_] = true;
    next_ = (next_ + 1) % kSlots;
}

std::optional<std::vector<std::uint32_t>> DelayedScalarReadback::pollBits(ID3D11DeviceContext* context) {
    std::optional<std::vector<std::uint32_t>> newest;
    while (pending_[oldest_]) {
        D3D11_MAPPED_SUBRESOURCE mapped{};
        if (context->Map(staging_[oldest_].Get(), 0, D3D11_MAP_READ, D3D11_MAP_FLAG_DO_NOT_WAIT, &mapped) != S_OK) break;
        std::vector<std::uint32_t> bits(count_);
        std::memcpy(bits.data(), mapped.pData, count_ * sizeof(std::uint32_t));
        context->Unmap(staging_[oldest_].Get(), 0);
        newest = std::move(bits);
        pending_[oldest_] = false;
        oldest_ = (oldest_ + 1) % kSlots;
    }
    return newest;
}

std::optional<float> DelayedScalarReadback::poll(ID3D11DeviceContext* context) {
    const std::optional<std::vector<std::uint32_t>> bits = pollBits(context);
    if (!bits) return std::nullopt;
    float value = 0.0f;
    std::memcpy(&value, bits->data(), sizeof(value));
    return value;
}

}  // namespace firmament
