// Bruneton and Neyret 2008 at render time (Bruneton and Neyret 2008, "Rendering"): the frame is the sum
// of three parts per pixel, each per unit sun irradiance times the sun's irradiance:
//  - in-scattered light between the camera x and the ray's end x0:
//      S(x, v) - T(x -> x0) S(x0, v), Rayleigh's part times P_R(nu), Mie's (rebuilt from its
//      red channel) times P_M(nu), both look-ups in the same half of the view zenith axis;
//  - the ground where the ray meets the Earth and nothing nearer is drawn: a Lambertian
//    surface of the model's albedo lit by the sun through the atmosphere and by the sky,
//      albedo / pi (T_sun(x0) max(mu_s, 0) + E(x0, mu_s)), seen through T(x -> x0);
//    other geometry keeps the radiance the scene gave it, seen through the same T;
//  - the sun's disc where the ray leaves the atmosphere, through T(x, v).
// Two passes, as Yusov's model's: ps_sky where nothing was drawn (the sky, the sun and the
// model's own ground), ps_aerial_perspective over geometry.
#include "atmosphere/bruneton/lookup.hlsli"
#include "atmosphere/render_passes.hlsli"

cbuffer BrunetonBuffer : register(b2) {
    BrunetonConstants bruneton;
};
cbuffer PassBuffer : register(b3) {
    BrunetonPassConstants sunDisc;
};

Texture2D<float4> transmittanceTable : register(t2);
Texture2D<float4> irradianceTable : register(t3);
Texture3D<float4> inscatterTable : register(t4);

// In-scattered radiance per unit sun irradiance from the table's RGBA.
float3 inscatteredRadiance(float4 rayleighMie, float nu) {
    return max(rayleighMie.rgb * rayleighPhase(nu) + mieFromRed(atmosphere, rayleighMie) * miePhase(nu, atmosphere.mieScattering.w), 0.0);
}

// The radiance this model gives the pixel, per the three parts above.
float3 modelRadiance(int2 pixel, float2 uv, float depth) {
    float3 scene = depth > 0.0 ? sceneRadiance.Load(int3(pixel, 0)).rgb : 0.0;
    float2 ndc = float2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
    float4 farPoint = mul(frame.clipToDirection, float4(ndc, 1.0, 1.0));
    float3 v = normalize(farPoint.xyz / farPoint.w);
    float3 s = frame.directionToSun.xyz;
    float rg = atmosphere.earth.x, rt = atmosphere.earth.z;
    float3 x = frame.cameraPosition.xyz + float3(0.0, rg, 0.0);  // from the Earth's centre
    float3 sunIrradiance = frame.sunIrradiance.rgb;
    // r^2 - Rg^2 from the camera's coordinates (ground plane y = 0 over the centre), so that the
    // metres of a camera near the ground are not lost to r^2 - Rg^2 in float.
    float3 c = frame.cameraPosition.xyz;
    float rho2 = dot(c.xz, c.xz) + c.y * (2.0 * rg + c.y);
    float h = rho2 / (length(x) + rg);
    float r = rg + h;

    // A camera above the atmosphere starts at the ray's entry.
    float offset = 0.0;
    if (r > rt) {
        float2 top = raySphere(x, v, rt);
        if (top.y <= 0.0 || top.x <= 0.0) {  // misses the atmosphere: space, the sun, geometry as it is
            bool sunHere = depth <= 0.0 && dot(v, s) > sunDisc.sun.x && raySphere(x, v, rg).y <= 0.0;
            return depth > 0.0 ? scene : (sunHere ? sunIrradiance * sunDisc.sun.y : 0.0);
        }
        offset = top.x;
        x += v * offset;
        h = atmosphere.earth.y - 1.0;
        r = rg + h;
        x *= r / length(x);
        rho2 = rho2At(atmosphere, h);
    }
    float mu = dot(x, v) / r;
    float muS = dot(x, s) / r;
    float nu = dot(v, s);
    bool toGround = mu < -sqrt(rho2) / r;  // below the horizon
    float groundDistance = toGround ? distanceToGround(r, mu, rho2) : 0.0;
    float end = toGround ? groundDistance : distanceToTop(atmosphere, r, mu, rho2);

    // What the ray ends on: geometry nearer than the Earth, the Earth (the model's ground), or the sky.
    bool geometry = depth > 0.0;  // reversed Z: 0 is the far plane, where nothing was drawn
    float geometryDistance = end;
    bool modelGround = toGround;
    if (geometry) {
        float4 world = mul(frame.inverseViewProjection, float4(ndc, depth, 1.0));
        geometryDistance = length(world.xyz / world.w - frame.cameraPosition.xyz) - offset;
        if (geometryDistance <= 0.0) return scene;
        // Geometry on the Earth's sphere (the orientation grid's ground) is the Earth. The test is
        // in depth, where the sphere's own depth and the stored one differ by rounding only, a
        // few parts in 1e7 with reversed Z. Both sides are bounded: terrain a few metres above or
        // below the sphere stays geometry.
        float4 sphereClip = mul(frame.viewProjection, float4(frame.cameraPosition.xyz + v * (offset + groundDistance), 1.0));
        float sphereDepth = sphereClip.z / sphereClip.w;
        modelGround = toGround && abs(depth - sphereDepth) <= 1e-5 * sphereDepth;
    }
    bool otherGeometry = geometry && !modelGround;
    float t = otherGeometry ? min(geometryDistance, end) : end;

    float4 fromCamera = lookUpInscatter(atmosphere, bruneton, inscatterTable, linearClamp, h, mu, muS, nu, toGround);
    float4 inscatter = fromCamera;
    float3 transmittance = 1.0;
    float3 radiance = 0.0;
    if (toGround || otherGeometry) {
        transmittance = transmittanceAlong(atmosphere, bruneton, transmittanceTable, linearClamp, r, mu, t);
        float3 x0 = x + v * t;
        float r0 = length(x0);
        float mu0 = dot(x0, v) / r0, muS0 = dot(x0, s) / r0;
        float h0 = modelGround ? 0.0 : max((rho2 + t * (t + 2.0 * r * mu)) / (r0 + rg), 0.0);  // as altitudeAt
        float4 fromEnd = lookUpInscatter(atmosphere, bruneton, inscatterTable, linearClamp, h0, mu0, muS0, nu, toGround);
        inscatter = max(fromCamera - transmittance.rgbr * fromEnd, 0.0);
        if (modelGround) {
            float3 sunLight = sunTransmittanceAt(atmosphere, bruneton, transmittanceTable, linearClamp, rg, muS0) * max(muS0, 0.0);
            float3 skyLight = irradianceAt(atmosphere, bruneton, irradianceTable, linearClamp, rg, muS0);
            radiance = transmittance * bruneton.ground.x / kPi * (sunLight + skyLight) * sunIrradiance;
        } else {
            radiance = transmittance * scene;
        }
    } else if (nu > sunDisc.sun.x) {
        radiance = sunTransmittanceAt(atmosphere, bruneton, transmittanceTable, linearClamp, r, mu) * sunIrradiance * sunDisc.sun.y;
    }
    return radiance + inscatteredRadiance(inscatter, nu) * sunIrradiance;
}

float4 ps_sky(FullscreenVertex input) : SV_Target {
    int2 pixel = int2(input.position.xy);
    float depth = sceneDepth.Load(int3(pixel, 0));
    if (depth > 0.0) discard;  // reversed Z: geometry, the other pass's
    return float4(modelRadiance(pixel, input.uv, depth), 1.0);
}

float4 ps_aerial_perspective(FullscreenVertex input) : SV_Target {
    int2 pixel = int2(input.position.xy);
    float depth = sceneDepth.Load(int3(pixel, 0));
    if (depth <= 0.0) discard;  // nothing drawn: the sky pass's
    return float4(modelRadiance(pixel, input.uv, depth), 1.0);
}
