#ifndef FIRMAMENT_LIGHTSHAFTS_EPIPOLAR_GEOMETRY_HLSLI
#define FIRMAMENT_LIGHTSHAFTS_EPIPOLAR_GEOMETRY_HLSLI
// Epipolar geometry on the screen (Yusov 2013, "Epipolar sampling"): N slices run from the
// epipole, the sun's projection, to the screen's border; samples along each slice. Every view
// ray through a slice lies in one plane with the ray towards the sun, so the in-scattering
// varies slowly along a slice and can be sampled sparsely there. With the sun behind the
// camera the slices converge on the anti-epipole, the projection of the direction away from
// the sun, and the same construction holds.
//
// Positions are in normalised device coordinates (NDC, y up). The slices' exit points go round
// the rectangle through the outermost pixels' centres: slice s exits at t = s / N of the way
// round, the left side top to bottom, then the bottom, the right side and the top.
// tests/gpu/EpipolarGeometryTest.cpp checks these functions against a CPU twin.
//
// The includer declares cbuffers `frame` (FrameConstants) and `epipolar` (EpipolarConstants).
#include "common/shared_structures.hlsli"
#include "lightshafts/lightshaft_structures.hlsli"

static const float kInvalidCoordinate = -1.0e4;  // a slice or sample off the screen
static const float kSkyDepth = 1.0e8;            // camera-space depth where nothing was drawn (m)
static const float kInvalidDepth = -1.0e8;       // camera-space depth of an invalid sample
static const uint kNoSource = 0xFFFF;            // the interpolation source of an invalid sample

// The centres of the outermost pixels in NDC: (left, bottom, right, top).
float4 screenBounds() {
    return float4(-1.0 + frame.screen.z, -1.0 + frame.screen.w, 1.0 - frame.screen.z, 1.0 - frame.screen.w);
}

// Within the rectangle of pixel centres, give or take a quarter pixel.
bool onScreen(float2 ndc) {
    float4 b = screenBounds();
    float2 margin = 0.5 * frame.screen.zw;
    return all(ndc >= b.xy - margin) && all(ndc <= b.zw + margin);
}

bool validSlice(float4 ends) {
    return ends.x > 0.5 * kInvalidCoordinate;
}

// Where slice `t` = s / N leaves the screen.
float2 sliceExit(float t) {
    float4 b = screenBounds();
    float round = t * 4.0;
    uint side = min((uint)floor(round), 3u);
    float p = round - (float)side;
    if (side == 0) return float2(b.x, lerp(b.w, b.y, p));  // left, downwards
    if (side == 1) return float2(lerp(b.x, b.z, p), b.y);  // bottom, rightwards
    if (side == 2) return float2(b.z, lerp(b.y, b.w, p));  // right, upwards
    return float2(lerp(b.z, b.x, p), b.w);                 // top, leftwards
}

// The part [near, far] of the line origin + k dir that lies within the rectangle of pixel
// centres (near > far when it misses): the slab method.
float2 rectangleSpan(float2 origin, float2 dir) {
    float4 b = screenBounds();
    float2 safe = abs(dir) < 1e-12 ? 1e-12 : dir;
    float2 k0 = (b.xy - origin) / safe;
    float2 k1 = (b.zw - origin) / safe;
    float2 kNear = min(k0, k1), kFar = max(k0, k1);
    return float2(max(kNear.x, kNear.y), min(kFar.x, kFar.y));
}

// Slice s's entry (xy) and exit (zw) points. The entry is the epipole when it lies on the
// screen, else where the line from it to the exit point enters the screen. A slice whose exit
// point is not where that line leaves the screen is invalid (its line runs away from the
// screen there): all its coordinates are kInvalidCoordinate. With `optimize` ("optimize
// sample locations"), a slice shorter than its samples on the screen is stretched beyond its
// exit point until its samples lie one pixel apart; those past the border are then invalid.
float4 sliceEndpoints(uint slice) {
    uint slices = epipolar.sampling.x, samples = epipolar.sampling.y;
    float2 exitPoint = sliceExit((float)slice / (float)slices);
    float2 epipole = epipolar.epipole.xy;
    float2 entry = epipole;
    if (epipolar.epipole.z == 0.0) {
        float2 toExit = exitPoint - epipole;
        float span = length(toExit);
        float2 k = rectangleSpan(epipole, toExit);
        // The exit point must be the far crossing, and the line must cross some screen first.
        if (abs(k.y - 1.0) * span > 1e-4 || (1.0 - k.x) * span < 1e-4) return kInvalidCoordinate;
        entry = epipole + toExit * max(k.x, 0.0);
    }
    if (epipolar.options.y != 0) {
        float pixels = length((exitPoint - entry) * frame.screen.xy * 0.5);
        exitPoint = entry + (exitPoint - entry) * max((float)(samples - 1) / max(pixels, 1e-3), 1.0);
    }
    return float4(entry, exitPoint);
}

// Sample i of a slice: from the entry (i = 0) to the exit (i = samples - 1).
float2 samplePosition(float4 ends, uint i) {
    return lerp(ends.xy, ends.zw, (float)i / (float)(epipolar.sampling.y - 1));
}

// Near the epipole ("epipole sampling density" applies): within a tenth of the screen's
// height of it.
bool nearEpipole(float2 ndc) {
    return length((ndc - epipolar.epipole.xy) * frame.screen.xy * 0.5) < 0.1 * frame.screen.y;
}

// Which slice a point of the screen lies on, as a fractional slice index in [0, N]: the line
// from the epipole through it leaves the screen at the exit point of that (fractional) slice.
float sliceOf(float2 ndc) {
    float4 b = screenBounds();
    float2 epipole = epipolar.epipole.xy;
    float2 d = ndc - epipole;
    if (dot(d, d) < 1e-14) d = float2(0.0, 1e-7);  // the epipole itself: every slice starts there
    float2 safe = abs(d) < 1e-12 ? (d > 0.0 ? 1e-12 : -1e-12) : d;  // the sign picks the side below
    // Where the line leaves each slab; the nearer of the two is where it leaves the screen.
    float2 kFar = (float2(d.x > 0.0 ? b.z : b.x, d.y > 0.0 ? b.w : b.y) - epipole) / safe;
    float k = min(kFar.x, kFar.y);
    float2 x = epipole + d * k;
    float t;
    if (kFar.x <= kFar.y)
        t = d.x > 0.0 ? 2.0 + saturate((x.y - b.y) / (b.w - b.y)) : saturate((b.w - x.y) / (b.w - b.y));
    else
        t = d.y > 0.0 ? 3.0 + saturate((b.z - x.x) / (b.z - b.x)) : 1.0 + saturate((x.x - b.x) / (b.z - b.x));
    return t * 0.25 * (float)epipolar.sampling.x;
}

#endif
