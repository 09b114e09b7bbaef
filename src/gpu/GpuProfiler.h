#pragma once
// GPU time per named pass from timestamp queries. Each frame brackets its passes with a
// disjoint query; results are read a few frames later so the CPU never waits on the GPU
// in the frame loop (flush() waits, for headless runs that print their timings).
//
//   profiler.beginFrame();
//   { auto pass = profiler.scope("Sky"); ...draw... }
//   profiler.endFrame();
#include <d3d11.h>
#include <wrl/client.h>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace firmament {

using Microsoft::WRL::ComPtr;

struct PassTiming {
    std::string name;
    double lastMs = 0.0;   // most recent resolved frame
    double meanMs = 0.0;   // over every resolved frame
    double minMs = 0.0;
    double maxMs = 0.0;
    std::uint64_t frames = 0;
    std::vector<double> samplesMs;  // every resolved frame's time, while keepSamples(true) (benchmarks)
};

class GpuProfiler {
public:
    GpuProfiler(ID3D11Device* device, ID3D11DeviceContext* context);

    void beginFrame();
    void endFrame();

    class Scope {
    public:
        Scope(GpuProfiler& profiler, std::string_view name);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        GpuProfiler& profiler_;
        size_t query_;
    };
    Scope scope(std::string_view name) { return Scope(*this, name); }

    // Waits for every frame still in flight and folds it into the statistics.
    void flush();
    // Forgets every statistic (a benchmark's measured frames start here); frames in flight are
    // waited for and dropped.
    void reset();
    // Keeps each frame's time of each pass in PassTiming::samplesMs, for medians.
    void keepSamples(bool keep) { keepSamples_ = keep; }

    // "Frame" (first timestamp to last of the frame) first, then passes in first-seen order.
    const std::vector<PassTiming>& timings() const { return timings_; }
    std::uint64_t disjointFrames() const { return disjointFrames_; }

private:
    static constexpr size_t kFramesInFlight = 4;
    struct PassQueries {
        size_t timing;  // index into timings_
        ComPtr<ID3D11Query> begin, end;
    };
    struct FrameQueries {
        ComPtr<ID3D11Query> disjoint, frameBegin, frameEnd;
        std::vector<PassQueries> passes;
        size_t used = 0;
        bool pending = false;
    };

    size_t beginPass(std::string_view name);
    void endPass(size_t query);
    bool resolve(FrameQueries& frame, bool wait);
    size_t timingIndex(std::string_view name);
    void record(size_t timing, double ms);

    ID3D11Device* device_;
    ID3D11DeviceContext* context_;
    std::array<FrameQueries, kFramesInFlight> frames_;
    size_t current_ = 0;
    bool inFrame_ = false;
    std::vector<PassTiming> timings_;
    std::uint64_t disjointFrames_ = 0;
    bool keepSamples_ = false;
};

}  // namespace firmament
