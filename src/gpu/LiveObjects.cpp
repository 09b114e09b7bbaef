#include "gpu/LiveObjects.h"

namespace firmament {

namespace {

// {5C0B7A52-3E41-4F2B-9A57-6E0A2C1D8F13}: the private-data slot that holds an object's tag.
constexpr GUID kLiveObjectTagSlot = {0x5c0b7a52, 0x3e41, 0x4f2b, {0x9a, 0x57, 0x6e, 0x0a, 0x2c, 0x1d, 0x8f, 0x13}};

// Lives exactly as long as the object that holds it; counts that object while it does.
class LiveObjectTag final : public IUnknown {
public:
    LiveObjectTag(std::shared_ptr<std::array<std::atomic<long>, kGpuObjectKinds>> counters, GpuObjectKind kind)
        : counters_(std::move(counters)), kind_(static_cast<int>(kind)) {
        ++(*counters_)[kind_];
    }
    ~LiveObjectTag() { --(*counters_)[kind_]; }
    LiveObjectTag(const LiveObjectTag&) = delete;
    LiveObjectTag& operator=(const LiveObjectTag&) = delete;

    HRESULT STDMETHODCALLTYPE QueryInterface(REFIID riid, void** object) override {
        if (!object) return E_POINTER;
        if (riid == __uuidof(IUnknown)) {
            *object = static_cast<IUnknown*>(this);
            AddRef();
            return S_OK;
        }
        *object = nullptr;
        return E_NOINTERFACE;
    }
    ULONG STDMETHODCALLTYPE AddRef() override { return ++references_; }
    ULONG STDMETHODCALLTYPE Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }

private:
    std::shared_ptr<std::array<std::atomic<long>, kGpuObjectKinds>> counters_;
    int kind_;
    std::atomic<ULONG> references_{1};
};

}  // namespace

long LiveObjectCounts::total() const {
    long sum = 0;
    for (long n : byKind) sum += n;
    return sum;
}

std::string LiveObjectCounts::describe() const {
    std::string parts;
    for (int k = 0; k < kGpuObjectKinds; ++k) {
        if (byKind[k] == 0) continue;
        if (!parts.empty()) parts += ", ";
        parts += std::string(kGpuObjectKindNames[k]) + " " + std::to_string(byKind[k]);
    }
    return std::to_string(total()) + (parts.empty() ? std::string() : " (" + parts + ")");
}

LiveObjectCounter::LiveObjectCounter() : counters_(std::make_shared<Counters>()) {
    for (auto& n : *counters_) n = 0;
}

void LiveObjectCounter::tag(ID3D11DeviceChild* object, GpuObjectKind kind) const {
    if (!object) return;
    auto* tag = new LiveObjectTag(counters_, kind);
    // The object takes its own reference (and drops a tag it held before under this slot).
    object->SetPrivateDataInterface(kLiveObjectTagSlot, tag);
    tag->Release();
}

LiveObjectCounts LiveObjectCounter::counts() const {
    LiveObjectCounts c;
    for (int k = 0; k < kGpuObjectKinds; ++k) c.byKind[k] = (*counters_)[k].load();
    return c;
}

}  // namespace firmament
