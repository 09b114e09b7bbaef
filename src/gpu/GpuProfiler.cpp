#include "gpu/GpuProfiler.h"

#include "gpu/Hresult.h"

#include <algorithm>
#include <thread>

namespace firmament {

namespace {
constexpr std::string_view kFrameName = "Frame";

ComPtr<ID3D11Query> createQuery(ID3D11Device* device, D3D11_QUERY type) {
    D3D11_QUERY_DESC desc{type, 0};
    ComPtr<ID3D11Query> query;
    check(device->CreateQuery(&desc, &query), "CreateQuery");
    return query;
}

template <typename T>
bool getData(ID3D11DeviceContext* context, ID3D11Query* query, T& out, bool wait) {
    for (;;) {
        const HRESULT hr = context->GetData(query, &out, sizeof out, wait ? 0 : D3D11_ASYNC_GETDATA_DONOTFLUSH);
        if (hr == S_OK) return true;
        if (!wait || FAILED(hr)) return false;
        std::this_thread::yield();
    }
}
}  // namespace

GpuProfiler::GpuProfiler(ID3D11Device* device, ID3D11DeviceContext* context) : device_(device), context_(context) {
    for (auto& frame : frames_) {
        frame.disjoint = createQuery(device_, D3D11_QUERY_TIMESTAMP_DISJOINT);
        frame.frameBegin = createQuery(device_, D3D11_QUERY_TIMESTAMP);
        frame.frameEnd = createQuery(device_, D3D11_QUERY_TIMESTAMP);
    }
    timingIndex(kFrameName);
}

void GpuProfiler::beginFrame() {
    FrameQueries& frame = frames_[current_];
    if (frame.pending) resolve(frame, true);  // the ring is full: this slot's results are needed now
    frame.used = 0;
    context_->Begin(frame.disjoint.Get());
    context_->End(frame.frameBegin.Get());
    inFrame_ = true;
}

void GpuProfiler::endFrame() {
    FrameQueries& frame = frames_[current_];
    context_->End(frame.frameEnd.Get());
    context_->End(frame.disjoint.Get());
    frame.pending = true;
    inFrame_ = false;
    current_ = (current_ + 1) % kFramesInFlight;
    // Collect whatever older frames are ready, without waiting.
    for (auto& older : frames_)
        if (older.pending && &older != &frames_[(current_ + kFramesInFlight - 1) % kFramesInFlight])
            resolve(older, false);
}

void GpuProfiler::flush() {
    // Oldest first, so that "last" is the newest frame.
    for (size_t i = 0; i < kFramesInFlight; ++i) {
        FrameQueries& frame = frames_[(current_ + i) % kFramesInFlight];
        if (frame.pending) resolve(frame, true);
    }
}

void GpuProfiler::reset() {
    flush();
    timings_.clear();
    timingIndex(kFrameName);  // always the first
    disjointFrames_ = 0;
}

size_t GpuProfiler::beginPass(std::string_view name) {
    if (!inFrame_) return SIZE_MAX;
    FrameQueries& frame = frames_[current_];
    if (frame.used == frame.passes.size())
        frame.passes.push_back({0, createQuery(device_, D3D11_QUERY_TIMESTAMP), createQuery(device_, D3D11_QUERY_TIMESTAMP)});
    PassQueries& pass = frame.passes[frame.used];
    pass.timing = timingIndex(name);
    context_->End(pass.begin.Get());
    return frame.used++;
}

void GpuProfiler::endPass(size_t query) {
    if (query == SIZE_MAX || !inFrame_) return;
    context_->End(frames_[current_].passes[query].end.Get());
}

bool GpuProfiler::resolve(FrameQueries& frame, bool wait) {
    D3D11_QUERY_DATA_TIMESTAMP_DISJOINT disjoint{};
    if (!getData(context_, frame.disjoint.Get(), disjoint, wait)) return false;
    frame.pending = false;
    if (disjoint.Disjoint || disjoint.Frequency == 0) {
        ++disjointFrames_;
        return true;
    }
    const double msPerTick = 1000.0 / static_cast<double>(disjoint.Frequency);
    auto elapsed = [&](ID3D11Query* begin, ID3D11Query* end, double& ms) {
        UINT64 t0 = 0, t1 = 0;
        if (!getData(context_, begin, t0, true) || !getData(context_, end, t1, true)) return false;
        ms = t1 >= t0 ? static_cast<double>(t1 - t0) * msPerTick : 0.0;
        return true;
    };
    double ms = 0.0;
    if (elapsed(frame.frameBegin.Get(), frame.frameEnd.Get(), ms)) record(0, ms);
    for (size_t i = 0; i < frame.used; ++i)
        if (elapsed(frame.passes[i].begin.Get(), frame.passes[i].end.Get(), ms)) record(frame.passes[i].timing, ms);
    return true;
}

size_t GpuProfiler::timingIndex(std::string_view name) {
    for (size_t i = 0; i < timings_.size(); ++i)
        if (timings_[i].name == name) return i;
    PassTiming timing;
    timing.name = std::string(name);
    timings_.push_back(std::move(timing));
    return timings_.size() - 1;
}

void GpuProfiler::record(size_t timing, double ms) {
    PassTiming& t = timings_[timing];
    t.lastMs = ms;
    t.minMs = t.frames == 0 ? ms : std::min(t.minMs, ms);
    t.maxMs = t.frames == 0 ? ms : std::max(t.maxMs, ms);
    t.meanMs += (ms - t.meanMs) / static_cast<double>(t.frames + 1);
    ++t.frames;
    if (keepSamples_) t.samplesMs.push_back(ms);
}

GpuProfiler::Scope::Scope(GpuProfiler& profiler, std::string_view name)
    : profiler_(profiler), query_(profiler.beginPass(name)) {}

GpuProfiler::Scope::~Scope() { profiler_.endPass(query_); }

}  // namespace firmament
