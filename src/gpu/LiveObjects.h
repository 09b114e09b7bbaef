#pragma once
// A count of the Direct3D 11 objects the program has made that are still alive, by kind.
//
// Wine has no debug layer (ID3D11Debug::ReportLiveDeviceObjects), so the program counts for
// itself: CountingDevice gives every object it makes a LiveObjectTag, a tiny COM object stored
// in the object's private data (SetPrivateDataInterface). The object holds the tag's only
// reference and releases it when it is destroyed, and the tag's destructor counts it gone. An
// object the runtime hands out again (identical state objects are shared) gets a new tag that
// replaces the old one under the same GUID, so it is counted once.
#include <d3d11.h>

#include <array>
#include <atomic>
#include <memory>
#include <string>
#include <string_view>

namespace firmament {

enum class GpuObjectKind { Buffer, Texture, View, Shader, InputLayout, State, Query, Other };
inline constexpr int kGpuObjectKinds = 8;
inline constexpr std::array<std::string_view, kGpuObjectKinds> kGpuObjectKindNames{
    "buffers", "textures", "views", "shaders", "input layouts", "states", "queries", "other"};

struct LiveObjectCounts {
    std::array<long, kGpuObjectKinds> byKind{};

    long total() const;
    long operator[](GpuObjectKind kind) const { return byKind[static_cast<int>(kind)]; }
    std::string describe() const;  // "412 (buffers 60, textures 80, ...)", kinds with none left out
};

class LiveObjectCounter {
public:
    LiveObjectCounter();

    // Attaches a tag to `object` (one the device has just made) and counts it.
    void tag(ID3D11DeviceChild* object, GpuObjectKind kind) const;
    // Alive now. Wine destroys objects on its command-stream thread, after their last Release:
    // for an exact figure, wait for the GPU first (waitForGpu).
    LiveObjectCounts counts() const;

private:
    using Counters = std::array<std::atomic<long>, kGpuObjectKinds>;
    std::shared_ptr<Counters> counters_;  // shared with the tags, which can outlive this counter
};

}  // namespace firmament
