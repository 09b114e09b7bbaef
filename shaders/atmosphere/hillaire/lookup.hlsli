#ifndef FIRMAMENT_HILLAIRE_LOOKUP_HLSLI
#define FIRMAMENT_HILLAIRE_LOOKUP_HLSLI
// Look-ups into Hillaire 2020's camera-independent tables, for every pass that reads them: the
// transmittance to the top, T(r, mu), and the multiple scattering Psi_ms(r, mu_s)
// (src/atmosphere/hillaire/HillairePrecomputation.h); and the sky irradiance E(r, mu_s) that
// Firmament adds for the ground. The tables and the sampler come in as arguments, so that each
// pass binds them where it likes.
#include "atmosphere/hillaire/parameterization.hlsli"

// A unit coordinate's place on a table of `size` texels: texel centres at u = i / (n - 1).
float2 hillaireTableUv(float2 unit, float2 size) { return 0.5 / size + unit * (1.0 - 1.0 / size); }

// T from radius r along the zenith cosine mu to the top of the atmosphere; zero below the
// horizon, where the Earth stops the ray (the sun behind the Earth).
float3 hillaireTransmittanceToTop(AtmosphereConstants a, HillaireConstants c, Texture2D<float4> table, SamplerState s, float r, float mu) {
    if (mu < -sqrt(hillaireHorizonDistanceSquared(a, r)) / r) return 0.0;
    return table.SampleLevel(s, hillaireTableUv(hillaireTransmittanceUnit(a, r, mu), c.transmittanceSize.xy), 0).rgb;
}

// Psi_ms at radius r with the sun at zenith cosine mu_s, per unit sun irradiance.
float3 hillaireMultipleScatteringAt(AtmosphereConstants a, HillaireConstants c, Texture2D<float4> table, SamplerState s, float r, float muS) {
    return table.SampleLevel(s, hillaireTableUv(hillaireMultipleScatteringUnit(a, r, muS), c.multipleScatteringSize.xy), 0).rgb;
}

// The sky's irradiance on a horizontal surface at radius r, per unit sun irradiance (the
// multiple-scattering table's mapping).
float3 hillaireIrradianceAt(AtmosphereConstants a, HillaireConstants c, Texture2D<float4> table, SamplerState s, float r, float muS) {
    return table.SampleLevel(s, hillaireTableUv(hillaireMultipleScatteringUnit(a, r, muS), c.irradianceSize.xy), 0).rgb;
}

#endif
