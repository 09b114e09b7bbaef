#pragma once
// A frame scored against a reference frame of the same view, from the captures' radiance before
// tone mapping (docs/clouds.md, "Against the reference": the clouds' particles against their
// path-traced reference). Used by tools/clouds-against-reference (through
// firmament_score_against_reference) and by the test that holds the particles to the committed
// references (CloudsAgainstReference).
#include "core/ExrImage.h"
#include "core/PngImage.h"

#include <cstddef>

namespace firmament::test {

// Over the technique's pixels of one frame.
struct FrameSums {
    double meanLuminance = 0.0;  // Rec. 709 Y of the radiance
    double redOverBlue = 0.0;    // the sum of red over the sum of blue
};

struct ReferenceScore {
    double exposure = 0.0;          // the one exposure both frames are tone-mapped at
    double hdrPsnrDb = 0.0;         // over every channel, the peak the reference's 99.9th percentile
    double toneMappedPsnrDb = 0.0;  // the golden test's PSNR of the two tone-mapped 8-bit frames
    std::size_t pixels = 0;         // the technique's pixels
    FrameSums reference, candidate;
    double meanLuminanceRatio = 0.0, redOverBlueRatio = 0.0;  // candidate over reference
    Rgba8Image referenceShown, candidateShown;                // the two tone-mapped frames
};

// `clear` is the view without the technique: its pixels are those where either frame's luminance
// differs from clear's by more than 5%. Both frames are tone-mapped at one exposure, the
// reference's log-average luminance brought to middle grey 0.18 (Reinhard et al. 2002, eq. 2),
// by the default operator (Uncharted 2, white point 3) through the CPU curves the tone mapping
// pass is tested against, so that neither frame's own automatic exposure enters the score. The
// HDR PSNR's peak is a percentile, so that a few unconverged bright paths do not set the scale.
// Throws std::invalid_argument when the three frames differ in size.
ReferenceScore scoreAgainstReference(const FloatRgbaImage& reference, const FloatRgbaImage& candidate, const FloatRgbaImage& clear);

// The two tone-mapped frames side by side, the candidate left.
Rgba8Image sideBySide(const ReferenceScore& score);

}  // namespace firmament::test
