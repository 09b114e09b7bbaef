// Hillaire 2020 at render time (section 5.3 and 5.4), in the two passes every model draws:
//  - ps_sky, where nothing was drawn: the sky-view table at the view's latitude and longitude,
//    and the sun's disc through T(x, v) where the view leaves the atmosphere;
//  - ps_aerial_perspective, over geometry at distance d: its radiance times the transmittance
//    to it plus the light scattered in between, both from the froxel volume at the pixel and d.
// Both times the sun's irradiance. Where the tables do not reach, each pixel is marched
// (march.hlsli, hillaire.aerialPerspective.w steps): from above the atmosphere (the paper does
// the same), and for geometry beyond the volume's depth (the paper stretches the last slice;
// Firmament marches instead). The ground is not drawn by the model: a view that meets the Earth
// where nothing was drawn shows only the light scattered on the way, as Yusov 2013's does.
#include "atmosphere/render_passes.hlsli"
#include "atmosphere/hillaire/camera.hlsli"

cbuffer HillaireBuffer : register(b2) {
    HillaireConstants hillaire;
};
cbuffer PassBuffer : register(b3) {
    HillairePassConstants sunConstants;
};

Texture2D<float4> transmittanceTable : register(t2);
Texture2D<float4> multipleScatteringTable : register(t3);
Texture2D<float4> skyViewTable : register(t4);
Texture3D<float4> aerialInscattering : register(t5);
Texture3D<float4> aerialTransmittance : register(t6);

float3 viewDirection(float2 uv) {
    float4 farPoint = mul(frame.clipToDirection, float4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, 1.0, 1.0));
    return normalize(farPoint.xyz / farPoint.w);
}

// The march over [0, length) of a view from where it starts in the atmosphere: steps growing
// away from a camera inside it (the aerosols lie near), equal from space (they lie at the far end
// of a view that meets the ground).
HillaireSegment marchPixel(HillaireView v, float length, bool fromSpace) {
    return hillaireMarch(atmosphere, hillaire, transmittanceTable, multipleScatteringTable, linearClamp, v, 0.0, length,
                         (int)hillaire.aerialPerspective.w, !fromSpace, hillaireEmptySegment());
}

// The sun's disc along a view that leaves the atmosphere, per unit sun irradiance.
float3 sunDisc(HillaireView v) {
    if (v.nu <= sunConstants.sun.x || hillaireViewMeetsGround(v)) return 0.0;
    return hillaireTransmittanceToTop(atmosphere, hillaire, transmittanceTable, linearClamp, v.r, v.mu) * sunConstants.sun.y;
}

float4 ps_sky(FullscreenVertex input) : SV_Target {
    int2 pixel = int2(input.position.xy);
    if (sceneDepth.Load(int3(pixel, 0)) > 0.0) discard;  // reversed Z: geometry, the other pass's
    float3 direction = viewDirection(input.uv), sunDir = frame.directionToSun.xyz;
    HillaireCamera cam = hillaireCamera(frame, atmosphere);
    float offset;
    HillaireView v = hillaireCameraView(atmosphere, cam, direction, sunDir, offset);
    float3 radiance;
    if (offset < 0.0) {  // from space, past the atmosphere: the sun's disc where the Earth does not hide it
        bool sunSeen = v.nu > sunConstants.sun.x && raySphere(cam.position, direction, atmosphere.earth.x).y <= 0.0;
        radiance = sunSeen ? sunConstants.sun.y : 0.0;
    } else if (cam.inSpace) {
        radiance = marchPixel(v, hillaireViewLength(atmosphere, v), true).radiance + sunDisc(v);
    } else {
        // The azimuth from the sun's: the angle between the two directions' horizontal parts.
        float3 viewAcross = direction - v.mu * cam.up, sunAcross = sunDir - v.muS * cam.up;
        float across = length(viewAcross) * length(sunAcross);
        float cosAzimuth = across > 1e-8 ? dot(viewAcross, sunAcross) / across : 1.0;
        float2 unit = hillaireSkyViewUnit(atmosphere, cam.r, v.mu, cosAzimuth);
        radiance = skyViewTable.SampleLevel(linearClamp, hillaireTableUv(unit, hillaire.skyView.xy), 0).rgb + sunDisc(v);
    }
    return float4(radiance * frame.sunIrradiance.rgb, 1.0);
}

float4 ps_aerial_perspective(FullscreenVertex input) : SV_Target {
    int2 pixel = int2(input.position.xy);
    float depth = sceneDepth.Load(int3(pixel, 0));
    if (depth <= 0.0) discard;  // nothing drawn: the sky pass's
    float3 scene = sceneRadiance.Load(int3(pixel, 0)).rgb;
    float4 world = mul(frame.inverseViewProjection, float4(input.uv.x * 2.0 - 1.0, 1.0 - input.uv.y * 2.0, depth, 1.0));
    float distance = length(world.xyz / world.w - frame.cameraPosition.xyz);
    HillaireCamera cam = hillaireCamera(frame, atmosphere);
    float volumeDepth = hillaire.aerialPerspective.y;
    float3 inscattered, transmittance;
    if (cam.inSpace || distance > volumeDepth) {
        float offset;
        HillaireView v = hillaireCameraView(atmosphere, cam, viewDirection(input.uv), frame.directionToSun.xyz, offset);
        if (offset < 0.0 || distance <= offset) return float4(scene, 1.0);  // nothing of the atmosphere in between
        HillaireSegment s = marchPixel(v, min(distance - offset, hillaireViewLength(atmosphere, v)), cam.inSpace);
        inscattered = s.radiance;
        transmittance = s.transmittance;
    } else {
        float n = hillaire.aerialPerspective.x;
        float3 uvw = float3(input.uv, 0.5 / n + distance / volumeDepth * (1.0 - 1.0 / n));
        inscattered = aerialInscattering.SampleLevel(linearClamp, uvw, 0).rgb;
        transmittance = aerialTransmittance.SampleLevel(linearClamp, uvw, 0).rgb;
    }
    return float4(scene * transmittance + inscattered * frame.sunIrradiance.rgb, 1.0);
}
