// The clouds' shading (Yusov 2014, "Pre-computed lighting"; docs/clouds.md, "Shading"): each
// particle, back to front, as the light it sends to the camera through the atmosphere, blended
// over the lit scene with premultiplied alpha.
//  - Opacity: 1 - e^(-tau), tau from the optical depth table along the view ray, cut at the
//    camera and at the scene's depth.
//  - The light at the particle: the sun's irradiance times the atmosphere's transmittance from the
//    particle to the sun, so that clouds at sunset glow red; and the sky's irradiance there, from
//    the tables of the model drawn (CLOUD_ATMOSPHERE 1: Yusov 2013's net density and ambient sky
//    light tables; 2: Bruneton and Neyret 2008's transmittance and irradiance tables; 3: Hillaire
//    2020's transmittance table and Firmament's sky irradiance table for his model).
//  - The particle's radiance: single scattering from the scattering table's sphere of the
//    particle's optical radius, at the view ray's entry point and direction against the sun,
//    times the Henyey-Greenstein phase function for the actual angle, lit by the sunlight through
//    the particles nearer the sun (clouds/particle_opacity.hlsl); multiple scattering by deck
//    diffusion through the particle's deck along the sun (its column unbroken by clear air): by
//    default the slab of the droplets' own medium solved by doubling and adding (Deck diffusion,
//    solved slab), or Eddington's in the delta-M scaled medium (Deck diffusion), or (Particle
//    table) the table's, of the particle alone;
//    plus the ambient light scattered by a white cloud (E_sky / pi, brighter at the particle's
//    top).
//  - Aerial perspective: over the stretch from the camera to where the ray enters the particle,
//    the atmosphere's transmittance and in-scattering (Yusov's render modes, Bruneton's
//    S(x, v) - T S(x0, v), or Hillaire's march), so that the cloud
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
Texture3D<float4> scatteringTable : register(t4);  // x single scattering, z the forward peak's (phases excluded), y multiple
StructuredBuffer<float4> particleSunColumn : register(t10);  // by slot: the optical depths nearer the sun and beyond, and their deck's parts (clouds/particle_opacity.hlsl)
Texture3D<float> deckDiffusionTable : register(t11);  // deck diffusion's light scattered more than once (src/clouds/DeckDiffusionTable.h)
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
    // The particle's column along the sun (clouds/particle_opacity.hlsl): x the optical depth
    // nearer the sun, y beyond it, z and w their parts in the particle's deck (no clear air between
    // them and the particle); and its own, through its centre (the optical depth table).
    float4 column = particleSunColumn[input.slot];
    ParticleHit axis;
    hitParticleFrom(p, p.centre.xyz - 4.0 * max(p.centre.w, p.shape.x) * sun, sun, axis);
    float own = particleOpticalDepth(p, axis, axis.far - axis.near, opticalDepthTable, linearWrap);
    float opticalRadius = 0.5 * own;
    // The sunlight at the particle through the column above: e^(-tau) of it unscattered, and, in
    // the delta-M scaled medium (Wiscombe 1977), up to e^(-(1 - g^2) tau) with the light that
    // was scattered into the droplets' forward peak on the way, no longer quite parallel.
    float direct = exp(-column.x);
    float scaledDirect = exp(-kScaledExtinctionShare * column.x);

    // The sun in the particle's unit-sphere space; the table's sphere of the particle's optical
    // radius. Its light leaves the whole chord of the sphere, of opacity 1 - e^(-2 tau cos): the
    // fragment's light is per unit opacity (the blending applies the particle's own).
    float3 l = normalize(float3(dot(sun, hit.tangent) / hit.scale.x, dot(sun, hit.normal) / hit.scale.y, dot(sun, hit.bitangent) / hit.scale.z));
    float3 scattered = particleScattering(hit.entry, hit.through, l, opticalRadius);
    float perOpacity = 1.0 / max(1.0 - exp(-2.0 * opticalRadius * saturate(dot(-hit.entry, hit.through))), 1e-4);
    // The particle's place in its deck along the sun (the column's part unbroken by clear air),
    // at its face towards the camera (mu = 1 looks at the face away from the sun); the sunlight
    // that reaches the deck crosses the clouds nearer the sun beyond the gaps at the scaled
    // extinction (their diffuse light leaves them through the gaps' open sides).
    float cosine = dot(direction, sun);
    float deckDepth = column.z + opticalRadius * (1.0 + cosine), deckTotal = column.z + own + column.w;
    float deckBeam = exp(-kScaledExtinctionShare * (column.x - column.z));
    float single, multiple;
    [branch] if (shading.light.y > 1.5) {
        // Deck diffusion, solved slab (the default), in the droplets' own medium: single
        // scattering of the beam that reaches the particle through its deck, with the droplets'
        // phase function, sharp forward peak and all; every later order, the forward peak's
        // included, from deck diffusion's table (less its single scattering: Nakajima and
        // Tanaka 1988).
        single = deckBeam * exp(-column.z) * scattered.x * henyeyGreenstein(cosine, kDropletAsymmetry);
        multiple = deckBeam * solvedSlabMultipleScattering(deckDepth, deckTotal, cosine);
    } else {
        // The delta-M scaled medium's: single scattering of the unscattered sunlight with the
        // droplets' phase function; the light scattered into the forward peak (on the way in, x's
        // share of the scaled first order, or inside the particle, z) with the scaled medium's
        // broader one. Multiple scattering: Eddington's deck diffusion less its single scattering,
        // or (Particle table) the table's, of the particle alone.
        float peak = henyeyGreenstein(cosine, kDropletAsymmetry / (1.0 + kDropletAsymmetry));
        single = direct * (scattered.x * henyeyGreenstein(cosine, kDropletAsymmetry) + scattered.z * peak) +
                 (scaledDirect - direct) * (kScaledExtinctionShare * scattered.x + scattered.z) * peak;
        multiple = shading.light.y > 0.5 ? scaledDirect * scattered.y * perOpacity : deckBeam * deckMultipleScattering(deckDepth, deckTotal, cosine);
    }
    // Ambient: the sky's light scattered by a white cloud, more at its top than at its base.
    float height = clamp(hit.entry.y, -1.0, 1.0);
    float3 ambient = skyLight * ((0.6 + 0.4 * height) / kTablePi);
    float3 radiance = sunLight * (single * perOpacity + multiple) + ambient;
    // Light terms (a study, not the default): one term alone, or none; the opacity and the aerial
    // perspective below are the same in every choice.
    [branch] if (shading.light.w > 0.5) {
        float term = shading.light.w;
        radiance = term < 1.5 ? sunLight * (single * perOpacity) : term < 2.5 ? sunLight * multiple : term < 3.5 ? ambient : float3(0.0, 0.0, 0.0);
    }

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
