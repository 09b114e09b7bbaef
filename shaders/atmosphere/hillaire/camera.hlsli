#ifndef FIRMAMENT_HILLAIRE_CAMERA_HLSLI
#define FIRMAMENT_HILLAIRE_CAMERA_HLSLI
// Where Hillaire 2020's per-frame passes look from: the camera against the Earth's centre, and
// the view along a direction from it (march.hlsli's HillaireView). A camera above the
// atmosphere starts its views where they enter it.
#include "atmosphere/hillaire/march.hlsli"

struct HillaireCamera {
    float3 position;  // from the Earth's centre (m)
    float3 up;        // the local vertical
    float r;          // |position|, never below the ground
    float rho2;       // r^2 - Rg^2
    bool inSpace;     // above the top of the atmosphere
};

// A view's start at the world position c (the ground plane y = 0 over the Earth's centre). rho^2
// comes from c's coordinates, so that the metres of a point near the ground survive single
// precision.
HillaireCamera hillaireCameraAt(AtmosphereConstants a, float3 c) {
    HillaireCamera cam;
    float rg = a.earth.x;
    cam.position = c + float3(0.0, rg, 0.0);
    cam.rho2 = max(dot(c.xz, c.xz) + c.y * (2.0 * rg + c.y), 0.0);
    cam.r = rg + cam.rho2 / (sqrt(rg * rg + cam.rho2) + rg);
    cam.up = cam.position / length(cam.position);
    cam.inSpace = cam.r > a.earth.z;
    return cam;
}

HillaireCamera hillaireCamera(FrameConstants f, AtmosphereConstants a) { return hillaireCameraAt(a, f.cameraPosition.xyz); }

// The same camera held at the top of the atmosphere when it is above it: where the tables that
// follow the camera are made (from space they are not read; render.hlsl marches each pixel).
HillaireCamera hillaireCameraInAtmosphere(FrameConstants f, AtmosphereConstants a) {
    HillaireCamera cam = hillaireCamera(f, a);
    if (cam.inSpace) {
        cam.r = a.earth.z;
        cam.rho2 = hillaireHorizonDistanceSquared(a, a.earth.z);
    }
    return cam;
}

// The view along the unit direction v from radius r (rho2 as above) with the local vertical up.
HillaireView hillaireViewAlong(float r, float rho2, float3 up, float3 v, float3 sunDir) {
    HillaireView view;
    view.r = r;
    view.rho2 = rho2;
    view.mu = dot(up, v);
    view.muS = dot(up, sunDir);
    view.nu = dot(v, sunDir);
    return view;
}

// The camera's view along v, from where it enters the atmosphere when the camera is above it:
// `offset` is the distance to that point (0 inside), negative when the view misses the atmosphere.
HillaireView hillaireCameraView(AtmosphereConstants a, HillaireCamera cam, float3 v, float3 sunDir, out float offset) {
    offset = 0.0;
    if (!cam.inSpace) return hillaireViewAlong(cam.r, cam.rho2, cam.up, v, sunDir);
    float2 top = raySphere(cam.position, v, a.earth.z);
    offset = top.y > 0.0 && top.x > 0.0 ? top.x : -1.0;
    float3 entry = cam.position + v * max(offset, 0.0);
    return hillaireViewAlong(a.earth.z, hillaireHorizonDistanceSquared(a, a.earth.z), entry / length(entry), v, sunDir);
}

#endif
