#pragma once
// An atmosphere model's sky scored against the reference atmosphere (docs/atmosphere.md,
// "Scores"): the rays of a capture's sampled pixels, the reference's light of every order along
// each (single scattering by quadrature, orders 2 to kScoreOrders by path tracing, the ground
// black), and the scores of a model's radiance at those pixels. Used by
// firmament_score_atmospheres (tools/score-atmospheres) and by the test that holds each model's
// sky to the reference (SkyAgainstReference).
#include "core/ExrImage.h"
#include "reference/ReferenceAtmosphere.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace firmament::test {

// The reference's orders: past the 16th the light changes by less than its paths' noise
// (ReferenceSky.TheOrdersPastTheSixteenthAddNothingVisible).
inline constexpr int kScoreOrders = 16;

struct PixelRay {
    int x = 0, y = 0;
    glm::dvec3 direction{0.0};
};

// The view rays of a grid of `columns` x `rows` pixels of a capture (its header's view and
// projection matrices, rebuilt as the program builds them), leaving out those within
// `sunMargin` radians of the sun (its disc and the aureole's peak, which no reference path
// resolves). The captures are read with readFloatExr, half float or 32-bit (--hdr-float32).
std::vector<PixelRay> sampledRays(const FloatExrFile& capture, int columns, int rows, double sunMargin);
glm::dvec3 directionToSun(const FloatExrFile& capture);

// The light of every order along a view from `start`, per unit sun irradiance, and its standard
// error (the path-traced orders' only), the paths drawn as `sampling` says.
atmosphere::ReferenceAtmosphere::Estimate referenceRadiance(
    const atmosphere::ReferenceAtmosphere& reference, glm::dvec3 start, glm::dvec3 view, glm::dvec3 sun, int paths, unsigned seed,
    atmosphere::ReferenceAtmosphere::PathSampling sampling = atmosphere::ReferenceAtmosphere::PathSampling::ByDensity);

double luminance(glm::dvec3 rgb);  // Rec. 709 Y

struct SkyScore {
    double hdrPsnrDb = 0.0;            // over every channel, the peak the reference's brightest channel
    double medianRelativeError = 0.0;  // of the luminance, |model - reference| / reference
    double p95RelativeError = 0.0;
    std::size_t pixels = 0;            // those with light in the reference
};

// `model` and `reference` at the same pixels; pixels whose reference luminance is not above
// 1e-9 of the brightest (views that miss the atmosphere) count in the PSNR only.
SkyScore scoreSky(const std::vector<glm::dvec3>& model, const std::vector<glm::dvec3>& reference);

// A capture's radiance at a pixel.
glm::dvec3 capturedRadiance(const FloatExrFile& capture, int x, int y);

}  // namespace firmament::test
