#ifndef FIRMAMENT_SINGLE_SCATTERING_HLSLI
#define FIRMAMENT_SINGLE_SCATTERING_HLSLI
// Single scattering along a ray by quadrature (Yusov 2013, "Computing single
// scattering"; Bruneton and Neyret 2008, eq. 5 without the ground):
//   L1(C, v, l) = P_R(v.l) S_R + P_M(v.l) S_M,
//   S_R = integral over [0, D] of T(C -> P) beta_R rho_R(h) T_sun(P) ds, S_M the same with beta_M rho_M,
// per unit sun irradiance, where T(C -> P) comes from the densities summed along the way and
// T_sun(P) from the net density table. The phases are constant along the ray, so the quadrature
// sums each species without its phase (what the tables store) and applies the phases at the end.
// The nodes crowd where the air is densest and the view ray still clear (RaySpacing).
#include "atmosphere/yusov/lookup.hlsli"

// Where a ray from `start` (relative to the Earth's centre) along viewDir leaves the
// atmosphere or meets the ground. `hitsGround` says which: a ray below the horizon
// (cos view < c_h) meets the ground, and the ray exactly along the horizon belongs to either
// half of the table, so its texels say. The ground distance -b - sqrt(max(b^2 - c, 0)) stays
// defined at the tangent and is 0 for a ray that starts on the ground.
float rayLengthInAtmosphere(AtmosphereConstants a, float3 start, float3 viewDir, bool hitsGround) {
    if (hitsGround) {
        float b = dot(start, viewDir);
        float c = dot(start, start) - a.earth.x * a.earth.x;
        return max(-b - sqrt(max(b * b - c, 0.0)), 0.0);
    }
    return max(raySphere(start, viewDir, a.earth.z).y, 0.0);
}

bool rayHitsGround(AtmosphereConstants a, float3 start, float3 viewDir) {
    float radius = length(start);
    return dot(start / radius, viewDir) < cosHorizon(a, radius - a.earth.x);
}

// Where the nodes of a ray's quadrature lie, in two steps.
//
// First, by altitude: the integrand falls roughly exponentially with altitude, and a ray is
// lowest at one end or at its perigee (the point nearest the Earth's centre), so the ray is split
// there and "geometric" nodes spaced away from it: their distances from the low point grow as
// H (e^(k t) - 1), t uniform, k = ln(1 + length / H). Every e-fold of distance gets the same number
// of nodes, and the aerosol layer of a rising ray is resolved by 30 of them where uniform steps put
// one or two in it (6% off in the median, 31% at worst, from 1 km). H = 4 Mie scale heights.
//
// Second, by the light the view ray loses: a grazing ray's low point lies hundreds of kilometres
// away, behind an optical depth of several, where nothing it scatters reaches the camera, and
// spacing by altitude alone crowds the nodes there (13% off at the horizon's dip from 40 km, 7%
// just above the horizon from 1 km). The nodes are placed at equal steps of
//   G(s) = t(s) + 1 - exp(-tau(s)),
// t(s) the geometric parameter (node i at i / steps) and tau the green optical depth from the
// start, taken over the geometric nodes and linear between them. On a clear ray G is t and
// nothing moves; on a thick one half the nodes go where the view ray is still clear.
// Measured against a converged integral on the CPU, for rays from 2 m to 40 km, grazing ones and
// those that dip to the horizon included: within 0.6% at 30 nodes (docs/atmosphere.md, "The
// integration's nodes"). Rays that dip into the Earth's shadow are the exception: the sun's
// transmittance falls to 0 within a few steps, and from 50 to 80 km such rays are 15% to 90% off
// at 30 nodes (2.6% at the table's 128).
struct RaySpacing {
    float lowPoint;      // distance to the ray's lowest point, in [0, length]
    float spread;        // H
    float inward;        // k of the part before the low point (0 when it starts there)
    float outward;       // k of the part after it
    float nodesInward;   // geometric nodes before the low point
    float nodesOutward;  // geometric nodes after it
};

RaySpacing raySpacing(AtmosphereConstants a, float3 start, float3 viewDir, float rayLength, int steps) {
    RaySpacing r;
    r.lowPoint = clamp(-dot(start, viewDir), 0.0, rayLength);
    r.spread = 4.0 * a.scaleHeights.y;
    r.inward = log(1.0 + r.lowPoint / r.spread);
    r.outward = log(1.0 + (rayLength - r.lowPoint) / r.spread);
    float share = r.inward / max(r.inward + r.outward, 1e-20);
    float inwardSteps = round(steps * share);
    if (r.inward > 0.0 && r.outward > 0.0) inwardSteps = clamp(inwardSteps, 1.0, steps - 1.0);
    r.nodesInward = inwardSteps;
    r.nodesOutward = steps - inwardSteps;
    return r;
}

// The distance along the ray of geometric node i (0 ... steps): 0 at the start, the length at the end.
float rayNode(RaySpacing r, int i) {
    if (i <= r.nodesInward)
        return r.nodesInward > 0.0 ? r.lowPoint - r.spread * (exp((1.0 - i / r.nodesInward) * r.inward) - 1.0) : 0.0;
    return r.lowPoint + r.spread * (exp((i - r.nodesInward) / r.nodesOutward * r.outward) - 1.0);
}

// The logarithmic mean (y - x) / ln(y / x), per channel: the mean over a step of a quantity that
// changes exponentially from x to y, which the densities nearly do. The arithmetic mean where
// the two are nearly equal or either is 0.
float3 logarithmicMean(float3 x, float3 y) {
    float3 logRatio = log(max(y, 1e-30) / max(x, 1e-30));
    float3 curved = step(1e-30, x) * step(1e-30, y) * step(1e-3, abs(logRatio));
    float3 safeLog = curved > 0.0 ? logRatio : 1.0;
    return lerp(0.5 * (x + y), (y - x) / safeLog, curved);
}

// The net density over a step whose ends have densities d0 and d1: Rayleigh and Mie
// exponential in between, the ozone's tent linear.
float3 stepNetDensity(float3 d0, float3 d1, float stepLength) {
    float3 mean = logarithmicMean(d0, d1);
    mean.z = 0.5 * (d0.z + d1.z);
    return mean * stepLength;
}

// A walk over the geometric nodes, carrying the green optical depth from the start.
struct GeometricWalk {
    float distance;
    float3 density;
    float depth;
};

GeometricWalk beginGeometricWalk(AtmosphereConstants a, float3 start) {
    GeometricWalk w;
    w.distance = 0.0;
    w.density = particleDensity(a, length(start) - a.earth.x);
    w.depth = 0.0;
    return w;
}

void stepGeometricWalk(AtmosphereConstants a, RaySpacing r, float3 start, float3 viewDir, float rayLength, int steps, int i,
                       inout GeometricWalk w) {
    float distance = i == steps ? rayLength : rayNode(r, i);
    float3 density = particleDensity(a, length(start + viewDir * distance) - a.earth.x);
    w.depth += opticalDepth(a, stepNetDensity(w.density, density, max(distance - w.distance, 0.0))).g;
    w.distance = distance;
    w.density = density;
}

// The quadrature's running state: the last node, and the sums up to it.
struct ScatteringSum {
    float distance;
    float3 density;
    float3 netDensity;             // from the start
    float3 sunTransmittance;       // at the last node
    SpeciesScattering integrand;   // scattered at the last node towards the camera, per unit length
    SpeciesScattering integral;    // the integral so far
};

// The integrand at a node of densities `density`, seen through `transmittance` and lit by `sun`.
SpeciesScattering scatteringIntegrand(AtmosphereConstants a, float3 density, float3 transmittance, float3 sun) {
    SpeciesScattering s;
    s.rayleigh = a.rayleighScattering.rgb * density.x * transmittance * sun;
    s.mie = a.mieScattering.rgb * density.y * transmittance * sun;
    return s;
}

// The sun's transmittance to a node.
float3 sunTransmittanceAt(AtmosphereConstants a, Texture2D<float4> netDensityLut, SamplerState linearClamp, float3 position, float3 sunDir) {
    float radius = length(position);
    return sunTransmittance(a, netDensityLut, linearClamp, radius - a.earth.x, dot(position / radius, sunDir));
}

// The mean of the integrand over a step from its ends. The view ray's part (density, phase and
// transmittance to the camera) changes exponentially along a step, and the logarithmic mean is
// exact for it. The sun's transmittance does not near the Earth's shadow: there it drops to 0
// faster than any exponential, the logarithmic mean underestimates the step (12% on rays from
// 50 to 80 km that dip into the shadow, at 128 nodes), and the arithmetic mean is the better
// rule. So the logarithmic mean is taken where the sun's transmittance changes by less than 2%
// over the step, the arithmetic one where it changes by more than 20% (a factor e^0.2), and a
// blend between.
float3 stepMeanIntegrand(float3 integrand0, float3 integrand1, float3 sun0, float3 sun1) {
    float3 sunChange = abs(log(max(sun1, 1e-30) / max(sun0, 1e-30)));
    float3 exponential = step(1e-30, sun0) * step(1e-30, sun1) * saturate((0.2 - sunChange) / 0.18);
    return lerp(0.5 * (integrand0 + integrand1), logarithmicMean(integrand0, integrand1), exponential);
}

// Adds the step from the last node to the node at `distance`.
void addScatteringNode(AtmosphereConstants a, Texture2D<float4> netDensityLut, SamplerState linearClamp, float3 start, float3 viewDir,
                       float3 sunDir, float distance, inout ScatteringSum sum) {
    float stepLength = max(distance - sum.distance, 0.0);
    float3 position = start + viewDir * distance;
    float3 density = particleDensity(a, length(position) - a.earth.x);
    sum.netDensity += stepNetDensity(sum.density, density, stepLength);
    float3 sun = sunTransmittanceAt(a, netDensityLut, linearClamp, position, sunDir);
    SpeciesScattering integrand = scatteringIntegrand(a, density, exp(-opticalDepth(a, sum.netDensity)), sun);
    sum.integral.rayleigh += stepMeanIntegrand(sum.integrand.rayleigh, integrand.rayleigh, sum.sunTransmittance, sun) * stepLength;
    sum.integral.mie += stepMeanIntegrand(sum.integrand.mie, integrand.mie, sum.sunTransmittance, sun) * stepLength;
    sum.distance = distance;
    sum.density = density;
    sum.sunTransmittance = sun;
    sum.integrand = integrand;
}

// S_R and S_M along the ray.
SpeciesScattering integrateSpeciesScattering(AtmosphereConstants a, Texture2D<float4> netDensityLut, SamplerState linearClamp, float3 start,
                                             float3 viewDir, float3 sunDir, float rayLength, int steps) {
    RaySpacing spacing = raySpacing(a, start, viewDir, rayLength, steps);
    // The ray's whole green optical depth, over the geometric nodes: where G ends.
    GeometricWalk walk = beginGeometricWalk(a, start);
    [loop] for (int i = 1; i <= steps; ++i) stepGeometricWalk(a, spacing, start, viewDir, rayLength, steps, i, walk);
    float placementEnd = 2.0 - exp(-walk.depth);

    ScatteringSum sum;
    sum.distance = 0.0;
    sum.density = particleDensity(a, length(start) - a.earth.x);
    sum.netDensity = 0.0;
    sum.sunTransmittance = sunTransmittanceAt(a, netDensityLut, linearClamp, start, sunDir);
    sum.integrand = scatteringIntegrand(a, sum.density, 1.0, sum.sunTransmittance);
    sum.integral.rayleigh = 0.0;
    sum.integral.mie = 0.0;
    // The nodes at equal steps of G, found while walking the geometric nodes again: within each
    // geometric step G is taken as linear in the distance.
    walk = beginGeometricWalk(a, start);
    float placement = 0.0;
    int node = 1;
    [loop] for (int j = 1; j <= steps; ++j) {
        float fromDistance = walk.distance, fromPlacement = placement;
        stepGeometricWalk(a, spacing, start, viewDir, rayLength, steps, j, walk);
        placement = (float)j / steps + 1.0 - exp(-walk.depth);
        [loop] while (node < steps && placementEnd * node / steps <= placement) {
            float share = (placementEnd * node / steps - fromPlacement) / (placement - fromPlacement);
            addScatteringNode(a, netDensityLut, linearClamp, start, viewDir, sunDir, lerp(fromDistance, walk.distance, share), sum);
            ++node;
        }
    }
    addScatteringNode(a, netDensityLut, linearClamp, start, viewDir, sunDir, rayLength, sum);
    return sum.integral;
}

// L1 along the ray.
float3 integrateSingleScattering(AtmosphereConstants a, Texture2D<float4> netDensityLut, SamplerState linearClamp, float3 start,
                                 float3 viewDir, float3 sunDir, float rayLength, int steps) {
    SpeciesScattering s = integrateSpeciesScattering(a, netDensityLut, linearClamp, start, viewDir, sunDir, rayLength, steps);
    return withPhases(a, s, dot(viewDir, sunDir));
}

#endif
