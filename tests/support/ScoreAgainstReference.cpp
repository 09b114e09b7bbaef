// firmament_score_against_reference REFERENCE.exr CANDIDATE.exr CLEAR.exr SIDE_BY_SIDE.png: a
// frame scored against a reference frame of the same view (tools/clouds-against-reference: the
// particles against the clouds' path-traced reference), from the captures' radiance before
// tone mapping; CLEAR is the view without the technique (support/ReferenceScore.h says which
// pixels are the technique's and how both frames are tone-mapped). Writes the two side by side
// (candidate left) and prints one JSON object:
//  - hdrPsnrDb: 10 log10(P^2 / MSE) over every channel of every pixel, P the reference's 99.9th
//    percentile of channel values (a percentile, so that a few unconverged bright paths do not
//    set the scale);
//  - toneMappedPsnrDb: the golden test's PSNR of the two tone-mapped 8-bit frames;
//  - pixels: the technique's pixels; for each frame over them, meanLuminance (Rec. 709 Y of the
//    radiance) and redOverBlue (the sum of red over the sum of blue), and their ratios, candidate
//    over reference.
#include "core/ExrImage.h"
#include "support/ReferenceScore.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <exception>

namespace {

nlohmann::json describe(const firmament::test::FrameSums& s) { return {{"meanLuminance", s.meanLuminance}, {"redOverBlue", s.redOverBlue}}; }

double finiteOr999(double db) { return std::isfinite(db) ? db : 999.0; }

}  // namespace

int main(int argc, char** argv) {
    using namespace firmament;
    if (argc != 5) {
        std::fprintf(stderr, "usage: firmament_score_against_reference REFERENCE.exr CANDIDATE.exr CLEAR.exr SIDE_BY_SIDE.png\n");
        return 2;
    }
    try {
        const test::ReferenceScore s = test::scoreAgainstReference(readFloatExr(argv[1]).image, readFloatExr(argv[2]).image, readFloatExr(argv[3]).image);
        writePng(argv[4], test::sideBySide(s));
        const nlohmann::json out{{"exposure", s.exposure},
                                 {"hdrPsnrDb", finiteOr999(s.hdrPsnrDb)},
                                 {"toneMappedPsnrDb", finiteOr999(s.toneMappedPsnrDb)},
                                 {"pixels", s.pixels},
                                 {"reference", describe(s.reference)},
                                 {"candidate", describe(s.candidate)},
                                 {"meanLuminanceRatio", s.meanLuminanceRatio},
                                 {"redOverBlueRatio", s.redOverBlueRatio}};
        std::printf("%s\n", out.dump().c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
