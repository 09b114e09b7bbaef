// Runs Hillaire 2020's parameterization (shaders/atmosphere/hillaire/parameterization.hlsli) at
// points the test chooses, so that it can be held to its CPU twin. Compiled with the program's
// shader folder as the include root.
#include "atmosphere/hillaire/parameterization.hlsli"

cbuffer AtmosphereBuffer : register(b0) {
    AtmosphereConstants atmosphere;
};

struct Query {
    float4 position;  // xyz: relative to the Earth's centre (m)
    float4 viewDir;   // xyz; or, for the inverses, xy: a table's unit coordinates
    float4 sunDir;    // xyz
};

StructuredBuffer<Query> queries : register(t0);
RWStructuredBuffer<float4> results : register(u0);

// The cosine of the angle between the horizontal parts of the view and the sun at `up`.
float cosAzimuthBetween(float3 up, float3 view, float3 sun) {
    float3 a = view - dot(view, up) * up, b = sun - dot(sun, up) * up;
    float la = length(a), lb = length(b);
    return la > 0.0 && lb > 0.0 ? dot(a, b) / (la * lb) : 1.0;
}

// (transmittance x_mu, x_r, sky view u, v) of each query's position and view.
[numthreads(64, 1, 1)]
void forward(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    float r = length(q.position.xyz);
    float3 up = q.position.xyz / r;
    float mu = dot(up, q.viewDir.xyz);
    results[id.x] = float4(hillaireTransmittanceUnit(atmosphere, r, mu),
                           hillaireSkyViewUnit(atmosphere, r, mu, cosAzimuthBetween(up, q.viewDir.xyz, q.sunDir.xyz)));
}

// (multiple scattering u, v, 0, 0) of each query's position and sun.
[numthreads(64, 1, 1)]
void multiple(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    float r = length(q.position.xyz);
    results[id.x] = float4(hillaireMultipleScatteringUnit(atmosphere, r, dot(q.position.xyz / r, q.sunDir.xyz)), 0.0, 0.0);
}

// The inverses of the unit coordinates viewDir.xy: (r, mu) of the transmittance table, and
// (mu, cosAzimuth) of the sky view at the query's radius.
[numthreads(64, 1, 1)]
void inverse(uint3 id : SV_DispatchThreadID) {
    Query q = queries[id.x];
    results[id.x] = float4(hillaireTransmittanceCoordinates(atmosphere, q.viewDir.xy),
                           hillaireSkyViewDirection(atmosphere, length(q.position.xyz), q.viewDir.xy));
}
