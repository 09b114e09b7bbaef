#pragma once
// The frame's render targets, owned by the renderer and handed to every pass through the
// FrameContext: the HDR radiance with its depth, the copy of the radiance that passes which
// read what they write (the atmosphere over geometry) read from, and the 8-bit output of a
// headless run (a window's output is its swap chain's back buffer). Techniques that need
// targets of their own (low-resolution or camera-space depth ones) keep them.
#include "gpu/Texture.h"

namespace firmament {

// The HDR radiance's floats: half (RGBA16F, what the frame is drawn in), or 32-bit for
// measurement (--hdr-float32: half floats end at 6e-8, where deep twilight's sky is).
enum class HdrPrecision { Half, Float32 };

class FrameTargets {
public:
    // (Re)creates every target at width x height; `withOutput`: also the 8-bit output target.
    void resize(ID3D11Device* device, int width, int height, bool withOutput, HdrPrecision precision = HdrPrecision::Half);

    // Copies the HDR frame as it is now into sceneCopy() and returns it.
    const Texture2D& copyHdr(ID3D11DeviceContext* context);

    const Texture2D& hdr() const { return hdr_; }          // RGBA16F (or RGBA32F) linear radiance (also a compute target)
    const Texture2D& depth() const { return depth_; }      // D32 reversed Z (1 near, 0 far, cleared to 0)
    const Texture2D& sceneCopy() const { return sceneCopy_; }
    const Texture2D& output() const { return output_; }    // 8-bit, sRGB-encoded (the swap chain's format); empty with a swap chain
    int width() const { return width_; }
    int height() const { return height_; }
    HdrPrecision precision() const { return precision_; }

private:
    Texture2D hdr_;
    Texture2D depth_;
    Texture2D sceneCopy_;
    Texture2D output_;
    int width_ = 0;
    int height_ = 0;
    HdrPrecision precision_ = HdrPrecision::Half;
};

}  // namespace firmament
