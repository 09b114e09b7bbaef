#ifndef FIRMAMENT_REFERENCE_PATHS_HLSLI
#define FIRMAMENT_REFERENCE_PATHS_HLSLI
// The clouds' path-traced reference on the GPU (docs/clouds.md, "Path-traced reference"): one
// Monte Carlo path through the medium the particles describe (clouds/reference_medium.hlsli).
// The CPU twin is CloudPathTracer (src/reference/CloudPathTracer.cpp); the GPU test holds the two
// to each other on the same particles and rays.
//  - Free flights by delta tracking (Woodcock et al. 1965) over the walk's majorants.
//  - At every collision the sun by next-event estimation: its irradiance there times Henyey and
//    Greenstein's phase function (1941) times the transmittance toward the sun by ratio tracking
//    (Novak et al. 2014); then a new direction from the phase function. Every bounce: Russian
//    roulette from the 64th on, on the throughput only, so a white cloud ends a path only when
//    the path leaves it (options.z bounds a path's events against a bug, far beyond any cloud).
//  - A path that leaves gathers the light arriving from beyond the clouds; one that reaches the
//    ground (Lambertian) gathers the sun there and bounces on, drawn by the cosine.
//
// The includer defines, before including this file, the lighting:
//   float3 sunAt(float3 x)                  the sun's irradiance at x before the clouds
//   float groundDistance(float3 x, float3 d) kFar when the ray misses the ground
//   float3 groundAlbedo(float3 x), float3 groundNormal(float3 x)
//   void segment(float3 x, float3 d, float distance, out float3 transmittance, out float3 light)
//                                           the air over [0, distance): its transmittance and the
//                                           light scattered in; at kFar, the sky's radiance
#include "clouds/reference_medium.hlsli"

static const float kFar = 3.0e38;
static const float kReferencePi = 3.14159265;
static const float kReferenceAsymmetry = 0.9;  // the droplets' Henyey-Greenstein g (particle_lighting.hlsli's)
static const uint kRouletteFrom = 64;

// A permuted congruential generator (O'Neill 2014), one uint of state per path.
float random01(inout uint state) {
    state = state * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    word = (word >> 22u) ^ word;
    return float(word >> 8) * (1.0 / 16777216.0);
}

// p(cos) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2))
float referencePhase(float cosine) {
    float g = kReferenceAsymmetry;
    float denominator = 1.0 + g * g - 2.0 * g * cosine;
    return (1.0 - g * g) / (4.0 * kReferencePi * denominator * sqrt(denominator));
}

// A unit vector at `cosine` from `axis`, at azimuth phi about it.
float3 around(float3 axis, float cosine, float phi) {
    float3 helper = abs(axis.x) < 0.9 ? float3(1.0, 0.0, 0.0) : float3(0.0, 1.0, 0.0);
    float3 u = normalize(cross(helper, axis));
    float3 v = cross(axis, u);
    float sine = sqrt(max(0.0, 1.0 - cosine * cosine));
    return normalize(cosine * axis + sine * (cos(phi) * u + sin(phi) * v));
}

// The phase function's cumulative distribution inverted in the cosine.
float3 samplePhase(float3 forward, inout uint state) {
    float g = kReferenceAsymmetry, u1 = random01(state), u2 = random01(state);
    float s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
    float cosine = clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
    return around(forward, cosine, 2.0 * kReferencePi * u2);
}

// Delta tracking (free flight) or ratio tracking (transmittance) along a ray, over [0, tMax):
// delta tracking returns the distance to the next real collision, or kNoCollision; ratio
// tracking an unbiased estimate of the transmittance, with Russian roulette once it is small (it
// ends long shadow rays). One function, called once per path step: the shader compiler inlines
// every call, and the medium's density is the costly part.
float track(float3 origin, float3 direction, float tMax, bool ratio, inout uint state) {
    MajorantWalk walk = beginWalk(origin, direction, tMax);
    float estimate = 1.0, t0, t1, majorant;
    [loop] while (nextStretch(walk, t0, t1, majorant)) {
        float t = t0;
        [loop] for (uint guard = 0; guard < 1048576u; ++guard) {
            t -= log(1.0 - random01(state)) / majorant;
            if (t >= t1) break;
            float extinction = referenceExtinction(origin + direction * t);
            if (!ratio) {
                if (random01(state) * majorant < extinction) return t;
                continue;
            }
            estimate *= max(0.0, 1.0 - extinction / majorant);
            if (estimate < 0.1) {
                if (random01(state) >= 0.5) return 0.0;
                estimate *= 2.0;
            }
        }
    }
    return ratio ? estimate : kNoCollision;
}

struct PathSample {
    float3 light;    // gathered along the path
    float escaped;   // 1 when the first flight reached the scene behind the clouds
};

// One path from `origin` along `direction`. With `sceneBehind`, the first flight ends at tScene
// (the frame drawn behind the clouds, which the caller blends by `escaped`); without, it goes on
// to the ground or beyond as any other flight. Each step of the loop traces one ray: a flight to
// the next event, or the shadow ray of the event before.
PathSample tracePath(float3 origin, float3 direction, float tScene, bool sceneBehind, uint eventLimit, inout uint state) {
    PathSample s;
    s.light = 0.0;
    s.escaped = 0.0;
    float3 sun = frame.directionToSun.xyz;
    float3 throughput = 1.0, x = origin, d = direction;
    float3 shadowWeight = 0.0;  // the sun's light at the last event, before the clouds' transmittance
    bool shadowRay = false, first = true, ending = false;
    uint events = 0;
    [loop] for (uint step = 0; step < 2u * eventLimit + 2u; ++step) {
        float3 along = shadowRay ? sun : d;
        float ground = groundDistance(x, along);
        float tMax = shadowRay ? kFar : (first && sceneBehind ? tScene : ground);
        // The ground hides the sun from below it.
        float result = shadowRay && ground < kFar ? 0.0 : track(x, along, tMax, shadowRay, state);
        if (shadowRay) {
            s.light += shadowWeight * result;
            shadowRay = false;
            if (ending) break;
            continue;
        }
        bool collided = result >= 0.0;
        if (!collided && first && sceneBehind) {
            s.escaped = 1.0;
            break;
        }
        // The air between: the camera and the first event, a cloud and the ground, or the sky beyond
        // (within a cloud it is left out, as the particles' shading leaves it out).
        bool escaping = !collided && ground >= kFar;
        float distance = collided ? result : ground;
        if (first || !collided) {
            float3 transmittance, light;
            segment(x, d, distance, transmittance, light);
            s.light += throughput * light;
            throughput *= transmittance;
        }
        if (escaping) break;
        x += d * distance;
        first = false;
        ++events;
        // The event: the sun by next-event estimation (its shadow ray next step), a new direction.
        float sunFactor;
        if (collided) {
            sunFactor = referencePhase(dot(sun, d));
            d = samplePhase(d, state);
        } else {
            float3 normal = groundNormal(x);
            throughput *= groundAlbedo(x);
            sunFactor = max(dot(normal, sun), 0.0) / kReferencePi;
            float u = random01(state);
            d = around(normal, sqrt(1.0 - u), 2.0 * kReferencePi * random01(state));
        }
        shadowWeight = throughput * sunAt(x) * sunFactor;
        shadowRay = sunFactor > 0.0;
        // The path ends after this event's shadow ray at the limit, or by Russian roulette.
        if (events >= kRouletteFrom && events < eventLimit) {
            float survive = min(1.0, max(throughput.x, max(throughput.y, throughput.z)));
            if (!(survive > 0.0) || random01(state) >= survive) ending = true;
            else throughput /= survive;
        }
        if (events >= eventLimit) ending = true;
        if (ending && !shadowRay) break;
    }
    return s;
}

#endif
