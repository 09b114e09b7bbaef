#pragma once
// Linked lists built on the GPU, one per texel of a grid (the clouds' per-pixel fragment lists
// and light-space tile lists): a head texture (R32_UINT, kNoNode when empty) with one row more
// than the grid, whose first two texels are counters ((0, height): the nodes asked for, those past
// the pool being dropped; (1, height): free for the user), and a pool of fixed-size nodes. The
// counts are read back a few frames late, never waiting, and a pool that was too small grows to
// 5/4 of what a frame asked for, up to a limit. Only the first build into a new pool (at start,
// after the grid or the first guess changed) waits for its counts, so that no frame after a
// start or a resize is drawn with lists cut short.
#include "gpu/Buffers.h"
#include "gpu/DelayedScalarReadback.h"
#include "gpu/Texture.h"

#include <d3d11.h>

#include <cstddef>
#include <optional>
#include <string>

namespace firmament {

class GpuLinkedLists {
public:
    // `what` names the pool in errors and in the log line when it grows.
    GpuLinkedLists(ID3D11Device* device, unsigned nodeStride, size_t maxPoolBytes, std::string what);

    // A width x height grid (the head texture recreated when it changes) and a pool of
    // `initialNodes` (recreated when the grid or `initialNodes` changes).
    void resize(ID3D11Device* device, int width, int height, unsigned initialNodes);
    // Grows the pool if a frame whose counts have come back asked for more, then empties every
    // list and zeroes the counters.
    void clear(ID3D11Device* device, ID3D11DeviceContext* context);
    // After the lists are built: the counters copied for the late read.
    void copyCounts(ID3D11DeviceContext* context);
    // After the lists are built (and their counts copied): true, once, when these were the first
    // lists of a new pool and they did not fit it. It waits for the GPU then (and only then), grows
    // the pool to 5/4 of what was asked, and the caller builds the lists again, into the new pool.
    bool firstBuildOverflowed(ID3D11Device* device, ID3D11DeviceContext* context);

    struct Counts {
        unsigned asked = 0;    // nodes asked for
        unsigned dropped = 0;  // of them, past the pool
        unsigned second = 0;   // the second counter
    };
    // The last built lists' counts; waits for the GPU (tests, benchmark).
    Counts read(ID3D11Device* device, ID3D11DeviceContext* context) const;
    // The newest counts that came back late, if any since the grid changed.
    std::optional<Counts> latest() const { return latest_; }

    unsigned capacity() const { return capacity_; }
    // What the lists hold on the GPU: the head texture (its counters' row included) and the pool.
    size_t bytes() const {
        return size_t{4} * static_cast<size_t>(heads_.width) * static_cast<size_t>(heads_.height) + size_t{stride_} * capacity_;
    }
    const Texture2D& heads() const { return heads_; }
    const StructuredBuffer& nodes() const { return nodes_; }

private:
    Counts countsOf(unsigned asked, unsigned second) const { return {asked, asked > capacity_ ? asked - capacity_ : 0u, second}; }
    // A pool for 5/4 of `asked` nodes, up to the limit; `why` ends the log line.
    void grow(ID3D11Device* device, unsigned asked, const std::string& why);

    unsigned stride_;
    size_t maxNodes_;
    std::string what_;
    int width_ = 0, height_ = 0;
    unsigned initialNodes_ = 0, capacity_ = 0;
    bool firstBuild_ = false;  // no lists were built into this pool yet
    Texture2D heads_;
    StructuredBuffer nodes_;
    DelayedScalarReadback countsReadback_;
    std::optional<Counts> latest_;
};

}  // namespace firmament
