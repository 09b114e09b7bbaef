// The clouds' shading (Yusov 2014, "Pre-computed lighting"; docs/clouds.md, "Shading"): each
// particle, back to front, as the light it sends to the camera through the atmosphere, blended
// over the lit scene with premultiplied alpha.
//  - Opacity: 1 - e^(-tau), tau from the optical depth table along the view ray, cut at the
//    camera and at the scene's depth.
//  - The light at the particle: the sun's irradiance times the atmosphere's transmittance from the
//    particle to the sun, so that clouds at sunset glow red, and through the particles nearer the
//    sun (clouds/particle_opacity.hlsl) at their full extinction for single scattering and at the
//    delta-M scaled one for multiple scattering; and the sky's irradiance there, from
//    the tables of the model drawn (CLOUD_ATMOSPHERE 1: Yusov 2013's net density and ambient sky
//    light tables; 2: Bruneton and Neyret 2008's transmittance and irradiance tables).
//  - The particle's radiance: from the scattering table of the reference sphere, looked up with
//    the view ray's entry point and direction against the sun: single scattering times the
//    Henyey-Greenstein phase function for the actual angle, plus multiple scattering; plus the
//    ambient light scattered by a white cloud (E_sky / pi, brighter at the particle's top).
//  - Aerial perspective: over the stretch from the camera to where the ray enters the particle,
//    the atmosphere's transmittance and in-scattering (Yusov's render modes, or Bruneton's
//    S(x, v) - T S(x0, v)), so that the cloud
//    stands in the haze, and the light scattered behind the cloud is hidden by its opacity:
//      C = L_behind (1 - a) + a (L_in(camera -> cloud) + T(camera -> cloud) L_cloud).
//  - Blending (CLOUD_BLENDING; docs/clouds.md, "Blending"): 0 plain alpha blending, the particle's
//    premultiplied light to the target; 1 the particle's fragment (its light not premultiplied,
//    extinction tau / length, visible stretch) appended to the pixel's list for the resolve; 2
//    volume-aware blending in primitive order through rasterizer-ordered views.
#include "atmosphere/atmosphere_structures.hlsli"
#include "clouds/optical_depth_table.hlsli"
#include "clouds/particle_shape.hlsli"
#include "clouds/volume_blending.hlsli"
#if CLOUD_BLENDING == 1
#define FRAGMENT_LISTS_APPEND
#include "clouds/fragment_lists.hlsli"
#elif CLOUD_BLENDING == 2
#include "clouds/ordered_blending.hlsli"
#endif

cbuffer AtmosphereBuffer : register(b2) { AtmosphereConstants atmosphere; };
cbuffer CloudShadingBuffer : register(b3) { CloudShadingConstants shading; };

Texture3D<float> opticalDepthTable : register(t2);
Texture2D<float> sceneDepth : register(t3);  // the frame's, or its low-resolution copy (Downscale)
Texture3D<float2> scatteringTable : register(t4);  // x single scattering (phase excluded), y multiple
StructuredBuffer<float> particleSunTransmittance : register(t10);  // by slot: through the particles nearer the sun (clouds/particle_opacity.hlsl)
SamplerState linearWrap : register(s0);
SamplerState linearClamp : register(s1);

#include "clouds/particle_lighting.hlsli"
#include "clouds/cloud_atmosphere.hlsli"

ShapeVertex vs_main(uint vertexId : SV_VertexID, uint instance : SV_InstanceID) { return shapeVertex(vertexId, instance); }

// The particle's fragment at this pixel: its light toward the camera through the atmosphere
// (per the sun's irradiance at the top of the atmosphere, not premultiplied), its extinction and
// visible stretch; false where the pixel misses it.
bool shadeFragment(ShapeVertex input, out ParticleFragment fragment) {
    fragment = (ParticleFragment)0;
    ParticlePixel px;
    if (!particlePixel(input, sceneDepth, shading.target.zw, opticalDepthTable, linearWrap, px) || px.opacity < 1e-4) return false;
    CloudParticle p = px.particle;
    ParticleHit hit = px.hit;
    float3 direction = px.direction;

    // The light at the particle's centre.
    float3 sun = frame.directionToSun.xyz;
    float3 sunLight, skyLight;
    lightAtPoint(p.centre.xyz, sunLight, skyLight);
    // Two transmittances through the particles nearer the sun: the sun's single scattering sees
    // their full extinction; the multiple scattering, computed in the delta-M scaled medium, the
    // scaled one, e^(-(1 - g^2) tau) = T^(1 - g^2).
    float sunTransmittance = particleSunTransmittance[input.slot];
    float scaledTransmittance = pow(sunTransmittance, kScaledExtinctionShare);

    // The sun in the particle's unit-sphere space.
    float3 l = normalize(float3(dot(sun, hit.tangent) / hit.scale.x, dot(sun, hit.normal) / hit.scale.y, dot(sun, hit.bitangent) / hit.scale.z));
    float2 scattered = particleScattering(hit.entry, hit.through, l);
    float phase = henyeyGreenstein(dot(direction, sun), kDropletAsymmetry);
    // Ambient: the sky's light scattered by a white cloud, more at its top than at its base.
    float height = clamp(hit.entry.y, -1.0, 1.0);
    float3 radiance = sunLight * (sunTransmittance * scattered.x * phase + scaledTransmittance * scattered.y) +
                      skyLight * ((0.6 + 0.4 * height) / kTablePi);

    // Through the atmosphere from the camera to where the ray enters the particle.
    float3 transmittance, inscattered;
    atmosphereSegment(frame.cameraPosition.xyz, direction, px.start, shading.modes, transmittance, inscattered);
    fragment.colour = frame.sunIrradiance.rgb * (inscattered + transmittance * radiance);
    fragment.extinction = px.opticalDepth / (px.end - px.start);
    fragment.front = px.start;
    fragment.back = px.end;
    return true;
}

#if CLOUD_BLENDING == 1
void ps_main(ShapeVertex input) {
    ParticleFragment fragment;
    if (!shadeFragment(input, fragment)) discard;
    appendFragment(uint2(input.position.xy), fragment, shading.blending.x, shading.blending.y);
}
#elif CLOUD_BLENDING == 2
float4 ps_main(ShapeVertex input) : SV_Target {
    ParticleFragment fragment;
    if (!shadeFragment(input, fragment)) discard;
    BlendedLight behind = mergeInPixelOrder(uint2(input.position.xy), fragment);
    return float4(behind.light, 1.0 - behind.transmittance);
}
#else
float4 ps_main(ShapeVertex input) : SV_Target {
    ParticleFragment fragment;
    if (!shadeFragment(input, fragment)) discard;
    float opacity = 1.0 - fragmentTransmittance(fragment);
    return float4(fragment.colour * opacity, opacity);
}
#endif
