#include "gpu/LinkedLists.h"

#include "core/Log.h"
#include "gpu/Readback.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace firmament {

GpuLinkedLists::GpuLinkedLists(ID3D11Device* device, unsigned nodeStride, size_t maxPoolBytes, std::string what)
    : stride_(nodeStride), maxNodes_(maxPoolBytes / nodeStride), what_(std::move(what)), countsReadback_(device, DXGI_FORMAT_R32_UINT, 2) {}

void GpuLinkedLists::resize(ID3D11Device* device, int width, int height, unsigned initialNodes) {
    const bool resized = width != width_ || height != height_ || !heads_.texture;
    if (resized) {
        width_ = width;
        height_ = height;
        heads_ = createColorTexture(device, width, height + 1, DXGI_FORMAT_R32_UINT, D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS);
        latest_.reset();
    }
    initialNodes = static_cast<unsigned>(std::min<size_t>(initialNodes, maxNodes_));
    if (resized || initialNodes != initialNodes_) {
        initialNodes_ = capacity_ = initialNodes;
        nodes_ = createStructuredBuffer(device, capacity_, stride_, nullptr, what_.c_str());
        firstBuild_ = true;
    }
}

void GpuLinkedLists::grow(ID3D11Device* device, unsigned asked, const std::string& why) {
    capacity_ = static_cast<unsigned>(std::min<size_t>(size_t{asked} * 5 / 4, maxNodes_));
    nodes_ = createStructuredBuffer(device, capacity_, stride_, nullptr, what_.c_str());
    log::info(what_ + ": the pool grows to " + std::to_string(capacity_) + " nodes (" + std::to_string(size_t{capacity_} * stride_ >> 20) +
              " MiB) after " + why);
}

bool GpuLinkedLists::firstBuildOverflowed(ID3D11Device* device, ID3D11DeviceContext* context) {
    if (!std::exchange(firstBuild_, false)) return false;
    const Counts counts = read(device, context);
    if (counts.asked <= capacity_ || capacity_ >= maxNodes_) return false;
    grow(device, counts.asked, "the first lists built into it asked for " + std::to_string(counts.asked) + "; they are built again");
    return true;
}

void GpuLinkedLists::clear(ID3D11Device* device, ID3D11DeviceContext* context) {
    if (const auto counts = countsReadback_.pollBits(context)) {
        latest_ = countsOf((*counts)[0], (*counts)[1]);
        if ((*counts)[0] > capacity_ && capacity_ < maxNodes_) grow(device, (*counts)[0], "a frame asked for " + std::to_string((*counts)[0]));
    }
    // Every head empty, then the counters zero (the row's other texels are never read).
    const UINT empty[4] = {0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu};
    context->ClearUnorderedAccessViewUint(heads_.uav.Get(), empty);
    const UINT zero[2] = {};
    const D3D11_BOX counters{0, static_cast<UINT>(height_), 0, 2, static_cast<UINT>(height_) + 1, 1};
    context->UpdateSubresource(heads_.texture.Get(), 0, &counters, zero, sizeof(zero), sizeof(zero));
}

void GpuLinkedLists::copyCounts(ID3D11DeviceContext* context) { countsReadback_.copy(context, heads_.texture.Get(), 0, static_cast<unsigned>(height_)); }

GpuLinkedLists::Counts GpuLinkedLists::read(ID3D11Device* device, ID3D11DeviceContext* context) const {
    if (!heads_.texture) return {};
    const ReadbackImage heads = readTexture2D(device, context, heads_.texture.Get());
    unsigned counters[2] = {};
    std::memcpy(counters, heads.bytes.data() + static_cast<size_t>(height_) * static_cast<size_t>(width_) * 4u, sizeof(counters));
    return countsOf(counters[0], counters[1]);
}

}  // namespace firmament
