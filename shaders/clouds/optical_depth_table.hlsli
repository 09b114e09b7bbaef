#ifndef FIRMAMENT_OPTICAL_DEPTH_TABLE_HLSLI
#define FIRMAMENT_OPTICAL_DEPTH_TABLE_HLSLI
// The particle's optical depth table (Yusov 2014, "Pre-computing optical depth"): for a ray that
// enters the unit sphere at s and travels along d, the mean density along its chord. Four
// coordinates, each 0..1 over its range:
//   u0 = theta_s / pi             the entry point's zenith (y is up)
//   u1 = phi_s / 2pi + 1/2        its azimuth, atan2(s.z, s.x) (wraps)
//   u2 = theta_d / (pi / 2)       the direction's angle from the inward normal -s
//   u3 = phi_d / 2pi + 1/2        its azimuth in the entry point's frame (wraps)
// The entry point's frame: Z = -s, X = normalize(Z x y), Y = Z x X (X = x at the poles). Packed
// into 3D as x = u1, y = u0, z = block u3 of N2 slices, each holding u2; u3 is filtered by hand
// between two blocks. The CPU twin is src/clouds/OpticalDepthTable.cpp.
static const float kTablePi = 3.14159265;

void entryFrame(float3 s, out float3 x, out float3 y, out float3 z) {
    z = -s;
    float3 side = cross(z, float3(0.0, 1.0, 0.0));
    float len = length(side);
    x = len > 1e-5 ? side / len : float3(1.0, 0.0, 0.0);
    y = cross(z, x);
}

// The entry point and direction of table coordinates u (each 0..1).
void opticalDepthRay(float4 u, out float3 s, out float3 d) {
    float thetaS = u.x * kTablePi, phiS = (u.y - 0.5) * 2.0 * kTablePi;
    s = float3(sin(thetaS) * cos(phiS), cos(thetaS), sin(thetaS) * sin(phiS));
    float3 x, y, z;
    entryFrame(s, x, y, z);
    float thetaD = u.z * 0.5 * kTablePi, phiD = (u.w - 0.5) * 2.0 * kTablePi;
    d = cos(thetaD) * z + sin(thetaD) * (cos(phiD) * x + sin(phiD) * y);
}

// Table coordinates of a ray entering the unit sphere at s (unit) along d (unit, inwards).
float4 opticalDepthCoordinates(float3 s, float3 d) {
    float3 x, y, z;
    entryFrame(s, x, y, z);
    float thetaS = acos(clamp(s.y, -1.0, 1.0));
    float phiS = atan2(s.z, s.x);
    float thetaD = acos(clamp(dot(d, z), 0.0, 1.0));
    // Along the axis (a chord through the centre) the azimuth is any: atan2(0, 0) is undefined.
    float dx = dot(d, x), dy = dot(d, y);
    float phiD = abs(dx) + abs(dy) > 1e-7 ? atan2(dy, dx) : 0.0;
    return float4(thetaS / kTablePi, phiS / (2.0 * kTablePi) + 0.5, thetaD / (0.5 * kTablePi), phiD / (2.0 * kTablePi) + 0.5);
}

// The table at u: trilinear within a block (x wraps, y and the block's slices clamp), linear
// by hand between the two blocks around u3 (wrapping). `sizes`: N0 (theta_s), N1 (phi_s), N2
// (theta_d), N3 (phi_d). y and the block's slices are clamped to their texel centres here, so a
// wrapping sampler filters none of them across an edge.
float sampleOpticalDepth(Texture3D<float> table, SamplerState linearWrap, float4 u, float4 sizes) {
    float y = clamp(u.x, 0.5 / sizes.x, 1.0 - 0.5 / sizes.x);
    float inBlock = clamp(u.z, 0.5 / sizes.z, 1.0 - 0.5 / sizes.z);
    float q = frac(u.w) * sizes.w - 0.5;
    float q0 = floor(q);
    float weight = q - q0;
    float block0 = q0 < 0.0 ? sizes.w - 1.0 : q0;
    float block1 = q0 + 1.0 >= sizes.w ? 0.0 : q0 + 1.0;
    float a = table.SampleLevel(linearWrap, float3(u.y, y, (block0 + inBlock) / sizes.w), 0.0);
    float b = table.SampleLevel(linearWrap, float3(u.y, y, (block1 + inBlock) / sizes.w), 0.0);
    return a + weight * (b - a);
}

#endif
