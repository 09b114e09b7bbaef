#ifndef FIRMAMENT_LIGHTSHAFTS_CAMERA_SPACE_DEPTH_HLSLI
#define FIRMAMENT_LIGHTSHAFTS_CAMERA_SPACE_DEPTH_HLSLI
// Camera-space depth (m along the camera's forward axis) of the point a view ray through `ndc`
// ends at: the geometry the depth buffer holds there (reversed Z, `depth` > 0), else the Earth's
// surface for a ray below the horizon, so that the horizon is a depth break like a silhouette;
// kSkyDepth above it. The epipolar passes compare depths in this form (camera_depth.hlsl for the
// pixels, sample_coordinates.hlsl for the samples, each at its own ray).
// The includer declares what epipolar_inputs.hlsli declares.
#include "atmosphere/yusov/single_scattering.hlsli"

float cameraSpaceDepth(float2 ndc, float depth) {
    if (depth > 0.0) {
        float4 world = mul(frame.inverseViewProjection, float4(ndc, depth, 1.0));
        return dot(world.xyz / world.w - frame.cameraPosition.xyz, epipolar.cameraForward.xyz);
    }
    float4 farPoint = mul(frame.clipToDirection, float4(ndc, 1.0, 1.0));
    float3 viewDir = normalize(farPoint.xyz / farPoint.w);
    float3 fromCentre = frame.cameraPosition.xyz + float3(0.0, atmosphere.earth.x, 0.0);
    if (!rayHitsGround(atmosphere, fromCentre, viewDir)) return kSkyDepth;
    return rayLengthInAtmosphere(atmosphere, fromCentre, viewDir, true) * dot(viewDir, epipolar.cameraForward.xyz);
}

#endif
