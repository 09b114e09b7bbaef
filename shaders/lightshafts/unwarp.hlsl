// Epipolar sampling, pass 11: from epipolar space back to the screen. Each pixel lies between
// two slices (the line from the epipole through it leaves the screen between their exit
// points); on each it falls between two samples. The four samples' in-scattering is blended
// with bilinear weights times bilateral depth weights, (tau / max(d, tau))^4 with d the relative
// difference of camera-space depth and tau the refinement threshold, so that light does not
// leak across depth breaks. The transmittance to the geometry is computed for the pixel, or
// blended from the samples like the light ("Extinction evaluation"). The pixel is composed as the
// atmosphere's passes compose it (atmosphere/yusov/shade_pixel.hlsli).
//
// Where the weights fail (sum < 0.01: no sample on either slice at the pixel's depth) the pixel
// is a depth break: with "Correction at depth breaks" it goes into a list that the next pass
// ray marches; without, it takes the light of the one sample among the four whose depth is
// nearest its own (a ground pixel under the horizon takes a ground sample, not the sky's).
// "Show depth breaks" paints such pixels magenta.
#define FIRMAMENT_NO_SHADE_PIXEL 1
#include "lightshafts/epipolar_inputs.hlsli"
#include "atmosphere/yusov/shade_pixel.hlsli"

RWTexture2D<float4> frameOut : register(u0);
RWStructuredBuffer<uint> breaksOut : register(u1);
RWBuffer<uint> breakArgumentsOut : register(u2);  // x, y, z groups, then the count

static const float kMinTotalWeight = 1e-2;

struct Blend {
    float3 light;
    float3 transmittance;
    float weight;
    float nearest;          // the smallest relative depth difference of a sample to the pixel
    float3 nearestLight;    // that sample's light and transmittance
    float3 nearestTransmittance;
};

float depthDifference(float z, float zs) {
    return abs(z - zs) / max(max(z, zs), 1.0);
}

// Bilateral weight of a sample at camera-space depth zs for a pixel at depth z.
float depthWeight(float z, float zs) {
    float threshold = epipolar.refinement.x;
    float w = threshold / max(depthDifference(z, zs), threshold);
    return w * w * w * w;
}

// Adds the two samples of `slice` around the pixel's projection on it.
void addSlice(inout Blend blend, uint slice, float sliceWeight, float2 ndc, float z) {
    float4 ends = sliceEnds.Load(int3(slice, 0, 0));
    if (sliceWeight <= 0.0 || !validSlice(ends)) return;
    float2 along = ends.zw - ends.xy;
    float last = (float)(epipolar.sampling.y - 1);
    float position = dot(ndc - ends.xy, along) / max(dot(along, along), 1e-12) * last;
    float before = floor(position);
    float f = position - before;
    [unroll] for (int k = 0; k < 2; ++k) {
        float index = before + (float)k;
        if (index < 0.0 || index > last) continue;
        int3 texel = int3((int)index, (int)slice, 0);
        float4 coordinates = sampleCoordinates.Load(texel);
        if (!validSample(coordinates)) continue;
        float3 light = interpolatedInscattering.Load(texel).rgb, transmittance = epipolarExtinction.Load(texel).rgb;
        float w = (k == 0 ? 1.0 - f : f) * sliceWeight * depthWeight(z, coordinates.z);
        blend.light += w * light;
        blend.transmittance += w * transmittance;
        blend.weight += w;
        float difference = depthDifference(z, coordinates.z);
        if (difference < blend.nearest) {
            blend.nearest = difference;
            blend.nearestLight = light;
            blend.nearestTransmittance = transmittance;
        }
    }
}

Blend blendSlices(float2 ndc, float z) {
    uint slices = epipolar.sampling.x;
    float slice = sliceOf(ndc);
    float before = floor(slice);
    float f = slice - before;
    uint s0 = ((uint)before) % slices;
    Blend blend;
    blend.light = 0.0;
    blend.transmittance = 0.0;
    blend.weight = 0.0;
    blend.nearest = 1.0e30;
    blend.nearestLight = 0.0;
    blend.nearestTransmittance = 1.0;
    addSlice(blend, s0, 1.0 - f, ndc, z);
    addSlice(blend, (s0 + 1) % slices, f, ndc, z);
    return blend;
}

[numthreads(PIXEL_GROUP, PIXEL_GROUP, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    float2 pixel = (float2)id.xy;
    if (any(pixel >= frame.screen.xy)) return;
    float2 ndc = ndcOf((pixel + 0.5) * frame.screen.zw);
    float z = cameraDepth.Load(int3(id.xy, 0));
    Blend blend = blendSlices(ndc, z);
    bool depthBreak = blend.weight < kMinTotalWeight;
    if (depthBreak && epipolar.options.w != 0) {
        frameOut[id.xy] = float4(frame.sunIrradiance.rgb * float3(1.0, 0.0, 1.0), 1.0);
        return;
    }
    if (depthBreak && epipolar.options.z == 0 && blend.nearest < 1.0e30) {
        blend.light = blend.nearestLight;
        blend.transmittance = blend.nearestTransmittance;
        blend.weight = 1.0;
    }
    if (blend.weight < kMinTotalWeight) {
        // Corrected (or, with no valid sample near at all, marched regardless): the next pass.
        uint slot;
        InterlockedAdd(breakArgumentsOut[3], 1, slot);
        breaksOut[slot] = packEntry(id.xy);
        return;
    }
    bool lightingOnly = lightShafts.options.x != 0;
    float depth = sceneDepth.Load(int3(id.xy, 0));
    PixelView v = pixelView(ndc, depth, lightShafts.sun.x);
    float3 radiance = v.geometry && !lightingOnly ? sceneRadiance.Load(int3(id.xy, 0)).rgb : 0.0;
    float3 transmittance = 1.0;
    if (v.geometry && v.inAtmosphere)
        transmittance = epipolar.modes.x != 0 ? blend.transmittance / blend.weight : transmittanceTo(v.ray, v.ray.length);
    float3 light = frame.sunIrradiance.rgb * blend.light / blend.weight * lightShafts.march.z;  // times the scattering scale
    frameOut[id.xy] = float4(composePixel(v, radiance, light, transmittance, !lightingOnly, lightShafts.sun.y), 1.0);
}
