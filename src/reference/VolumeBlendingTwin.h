#pragma once
// Volume-aware blending of cloud particles on the CPU (Yusov 2014, "Volume-aware blending";
// docs/clouds.md, "Blending"): the twin of shaders/clouds/volume_blending.hlsli, which the
// per-pixel list resolve and the rasterizer-ordered path run on the GPU.
//
// A particle's fragment is the stretch of the view ray inside it, [front, back] metres from the
// camera, with a uniform extinction and the radiance the particle sends toward the camera. Two
// fragments that overlap are merged into one over their union, the front, intersection and back
// stretches composed with the paper's formulas; a fragment wholly in front of the stored one
// pushes the stored one behind, where it is blended as usual.
#include <glm/vec3.hpp>

#include <vector>

namespace firmament {

struct ParticleFragment {
    glm::vec3 colour{0.0f};   // radiance toward the camera, not premultiplied
    float extinction = 0.0f;  // rho * beta (1/m); the transmittance over d metres is e^(-extinction d)
    float front = 0.0f;       // distances from the camera (m), front < back
    float back = 0.0f;
};

// Light over the scene: `light` premultiplied, the scene behind seen through `transmittance`.
struct BlendedLight {
    glm::vec3 light{0.0f};
    float transmittance = 1.0f;
};

// The fragment's own transmittance e^(-extinction (back - front)).
float fragmentTransmittance(const ParticleFragment& f);
// `f` over `behind`: C = c (1 - T) + T C_behind, T = T_f T_behind.
BlendedLight blendOver(const ParticleFragment& f, const BlendedLight& behind);

// Two overlapping fragments as one over [min front, max back] (Yusov 2014):
//   T_front = e^(-rho_f d_f beta), C_front = c_f (1 - T_front), likewise the back stretch;
//   T_isec = e^(-(rho_0 + rho_1) d_i beta), C_isec = (c_0 rho_0 + c_1 rho_1) / (rho_0 + rho_1) (1 - T_isec);
//   T = T_front T_isec T_back, c = (C_front + C_isec T_front + C_back T_front T_isec) / (1 - T),
// with the uniform extinction that gives T over the union. A nested fragment has no front or back
// stretch of its own: the outer one owns both.
ParticleFragment mergeOverlapping(const ParticleFragment& a, const ParticleFragment& b);

// One pixel's blending as fragments arrive back to front: the stored fragment and what has
// been pushed behind it.
struct VolumeBlend {
    BlendedLight behind;
    ParticleFragment current;
    bool hasCurrent = false;

    // A fragment in front of the stored one pushes it behind; an overlapping one merges with it;
    // one wholly behind it (the particles' order is by centre, not by fragment) goes behind it.
    void add(const ParticleFragment& f);
    // The stored fragment over what is behind it.
    BlendedLight resolve() const;
};

// The per-pixel list's resolve: at most `maxFragments` fragments, those nearest the camera by
// their back distance (the rest are dropped and counted in `dropped`), added in order of
// decreasing back distance, so that a fragment pushed behind is never overlapped by a later one.
BlendedLight blendVolumes(std::vector<ParticleFragment> fragments, int maxFragments, int* dropped = nullptr);
// Plain alpha blending of the fragments in the order given ("Volumetric blending" off).
BlendedLight blendAlpha(const std::vector<ParticleFragment>& backToFront);

}  // namespace firmament
