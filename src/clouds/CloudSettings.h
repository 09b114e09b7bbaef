#pragma once
// Settings of the clouds (section "clouds"): a layer of volumetric particles generated on the
// GPU in rings of cells around the camera (Yusov 2014). The controls of Yusov's cloud sample
// with its ranges and defaults (docs/clouds.md, "Controls").
#include "core/Settings.h"

#include <array>
#include <string_view>

namespace firmament {

// "Show particles": the particles as their bounding ellipsoids, or with the transparency their
// optical depth table gives (the steps of Yusov 2014's algorithm overview).
enum class ParticleView { Off, BoundingShapes, OpticalDepth };
inline constexpr std::array<std::string_view, 3> kParticleViewNames{"Off", "Bounding shapes", "Optical depth"};
// "Particle density": the density inside a particle, from which its optical depth table is
// computed (Yusov 2014, "3D noise generation").
enum class ParticleDensityMethod { RadialNoise, ThresholdedNoise, Pyroclastic };
inline constexpr std::array<std::string_view, 3> kParticleDensityMethodNames{"Radial fall-off and noise", "Thresholded noise", "Pyroclastic"};
// "Cloud density resolution": the side of the density map, a power of two from 128 to 1024.
inline constexpr std::array<std::string_view, 4> kCloudDensityResolutionNames{"128", "256", "512", "1024"};
// "Blending path" of volume-aware blending: rasterizer-ordered views where the device has them
// (Auto), or each pixel's fragments in a list sorted by a resolve pass (src/clouds/ParticleBlending.h).
enum class BlendingPath { Auto, RasterizerOrdered, PerPixelLists };
// "Downscale": the clouds rendered at 1/1, 1/2 or 1/4 of the frame's resolution along each side.
inline constexpr std::array<std::string_view, 3> kCloudDownscaleNames{"1x", "2x", "4x"};
// "Light-space map resolution": tiles along a side of the grid seen from the sun.
inline constexpr std::array<std::string_view, 4> kLightSpaceResolutionNames{"256", "512", "1024", "2048"};
inline constexpr std::array<std::string_view, 3> kBlendingPathNames{"Auto", "Rasterizer-ordered views", "Per-pixel lists"};
// "Shafts from clouds": how the light shafts see the clouds (Yusov 2014's sample): not at all; as
// casters drawn into the shadow cascades where they let through less than half of the light; or
// through their light-space transparency map, sampled at every step of the march.
enum class ShaftsFromClouds { None, ShadowMap, TransparencyMap };
inline constexpr std::array<std::string_view, 3> kShaftsFromCloudsNames{"None", "Shadow map", "Transparency map"};

// "Renderer": the particles shaded from their tables (Yusov 2014), or the path-traced reference of
// the medium they describe (docs/clouds.md, "Path-traced reference"), as brute force sits beside
// epipolar sampling.
enum class CloudRenderer { Particles, PathTracedReference };
inline constexpr std::array<std::string_view, 2> kCloudRendererNames{"Particles", "Reference (path traced)"};

// "Multiple scattering": the light scattered more than once, from deck diffusion through each
// particle's deck along the sun, its column unbroken by clear air (docs/clouds.md, "Deck
// diffusion"): by default the slab of the droplets' own medium solved by doubling and adding
// (deck diffusion's table; Deck diffusion, solved slab); for comparison, Eddington's radiance in
// the delta-M scaled medium (Deck diffusion), or the scattering table's multiple scattering of
// the particle alone, dimmed by the delta-M scaled transmittance of the particles nearer the sun
// (Particle table, Yusov 2014's approach).
enum class MultipleScattering { DeckDiffusion, ParticleTable, SolvedSlab };
inline constexpr std::array<std::string_view, 3> kMultipleScatteringNames{"Deck diffusion", "Particle table", "Deck diffusion, solved slab"};

// "Light terms": the particles' light, or one of its terms alone, the others taken out (a study of
// where a cloud's light comes from; docs/clouds.md, "Against the reference"): the sunlight
// scattered once, the sunlight scattered more than once, the sky's light, or none (the clouds'
// opacity alone, black in the haze in front of them). The aerial perspective and the blending
// are the same in every choice, so the three terms add up to the whole plus twice None.
enum class CloudLightTerms { All, SunOnce, SunMoreThanOnce, Sky, None };
inline constexpr std::array<std::string_view, 5> kCloudLightTermsNames{"All", "Sun, scattered once", "Sun, scattered more than once", "Sky",
                                                                       "None"};

struct CloudSettings {
    // "Enable clouds": the particles shaded from their tables and blended over the scene (with
    // either atmosphere model drawn alone).
    bool enabled = true;
    CloudRenderer renderer = CloudRenderer::Particles;  // "Renderer"
    // "Reference paths per frame": paths per pixel the reference adds each frame to its
    // accumulation, which starts over when the view, the sun or the clouds change.
    int referencePaths = 1;
    // "Reference pixel stride": each frame the reference traces one pixel of every stride x stride
    // block, in turn, so a frame costs 1 / stride^2 of a full pass; until a pixel's turn comes it
    // shows its block's first pixel. 1 traces every pixel every frame.
    int referenceStride = 1;
    // "Volumetric blending": particles that intersect are merged as volumes (Yusov 2014); off,
    // plain back-to-front alpha blending, for comparison.
    bool volumetricBlending = true;
    BlendingPath blendingPath = BlendingPath::Auto;  // "Blending path"
    // "Downscale": the clouds rendered at this fraction of the frame's resolution (1, 2 or 4),
    // then upsampled bilaterally by depth.
    int downscale = 2;
    // "Light-space map resolution": the sun's view of the particles in which each particle's
    // opacity toward the sun is found (a power of two, 256 to 2048).
    int lightSpaceResolution = 512;
    // "Light occlusion": each particle lit through the particles nearer the sun (light-space
    // tiling, Yusov 2014); off, every particle sees the sun unoccluded, as in part 1.
    bool lightOcclusion = true;
    MultipleScattering multipleScattering = MultipleScattering::SolvedSlab;  // "Multiple scattering"
    CloudLightTerms lightTerms = CloudLightTerms::All;  // "Light terms"
    // "Opacity early exit": a particle's walk along the sun stops once the column it has found is
    // 256 thick (kOpacityEarlyExitDepth, src/clouds/LightSpace.h; Yusov 2014 stops once the sun's
    // transmittance is below 0.01); off, it walks the tile's whole list.
    bool opacityEarlyExit = true;
    // "Visibility culling": only the particles whose bounding sphere reaches into the view are
    // drawn (Yusov 2014's visibility pass); off, every particle is drawn, for comparison. The
    // passes seen from the sun take every particle either way.
    bool visibilityCulling = true;
    // "Cloud shadows": the clouds' light-space transparency map drawn each frame, shadowing the
    // terrain and, by Shafts from clouds, the light shafts; off, the clouds cast no shadow.
    bool shadows = true;
    // "Shafts from clouds": the clouds' shadows in the light shafts. The terrain is shadowed by
    // the transparency map in every mode.
    ShaftsFromClouds shaftsFromClouds = ShaftsFromClouds::TransparencyMap;
    // "Show particles": each particle drawn over the scene as its bounding ellipsoid lit by the
    // sun, or white with the transparency of its optical depth (docs/clouds.md).
    ParticleView showParticles = ParticleView::Off;
    ParticleDensityMethod particleDensity = ParticleDensityMethod::RadialNoise;
    int densityResolution = 512;      // "Cloud density resolution"
    float cloudiness = 0.65f;         // "Cloudiness": the share of the sky the density map covers
    float altitude = 3000.0f;         // "Altitude" of the layer's middle above the surface (m)
    float thickness = 700.0f;         // "Thickness" of the layer (m)
    float speed = 0.2f;               // "Speed": the wind moves the density map at speed x 50 m/s
    float particleDistance = 2.0e5f;  // "Particle distance": no particle beyond it (m); the outer ring's half-width
    int rings = 5;                    // "Rings": each ring's cells are twice the size of the inner ring's
    int ringDimension = 128;          // "Ring dimension": cells along a ring's side (a multiple of 4 is used)
    int maxLayers = 4;                // "Max layers": particles a cell stacks through the thickness

    // The ring dimension the grid uses: a multiple of 4, so that the inner ring fills the
    // middle half of the next one exactly.
    int effectiveRingDimension() const { return ringDimension / 4 * 4; }

    void visit(SettingsVisitor& v) {
        v.field("enabled", enabled, "Enable clouds");
        v.choice("renderer", renderer, kCloudRendererNames, "Renderer");
        v.field("referencePaths", referencePaths, {1, 64}, "Reference paths per frame");
        v.field("referenceStride", referenceStride, {1, 8}, "Reference pixel stride");
        v.choice("showParticles", showParticles, kParticleViewNames, "Show particles");
        v.field("shadows", shadows, "Cloud shadows");
        v.choice("shaftsFromClouds", shaftsFromClouds, kShaftsFromCloudsNames, "Shafts from clouds");
        v.field("volumetricBlending", volumetricBlending, "Volumetric blending");
        v.choice("blendingPath", blendingPath, kBlendingPathNames, "Blending path");
        v.powerOfTwoChoice("downscale", downscale, 1, kCloudDownscaleNames, "Downscale");
        v.field("lightOcclusion", lightOcclusion, "Light occlusion");
        v.choice("multipleScattering", multipleScattering, kMultipleScatteringNames, "Multiple scattering");
        v.choice("lightTerms", lightTerms, kCloudLightTermsNames, "Light terms");
        v.powerOfTwoChoice("lightSpaceResolution", lightSpaceResolution, 256, kLightSpaceResolutionNames, "Light-space map resolution");
        v.field("opacityEarlyExit", opacityEarlyExit, "Opacity early exit");
        v.field("visibilityCulling", visibilityCulling, "Visibility culling");
        v.choice("particleDensity", particleDensity, kParticleDensityMethodNames, "Particle density");
        v.powerOfTwoChoice("densityResolution", densityResolution, 128, kCloudDensityResolutionNames, "Cloud density resolution");
        v.field("cloudiness", cloudiness, {0.0f, 1.0f}, "Cloudiness");
        v.field("altitude", altitude, {1000.0f, 10000.0f}, "Altitude");
        v.field("thickness", thickness, {100.0f, 1500.0f}, "Thickness");
        v.field("speed", speed, {0.0f, 2.0f}, "Speed");
        v.field("particleDistance", particleDistance, {1.0e4f, 5.0e5f, true}, "Particle distance");
        v.field("rings", rings, {1, 8}, "Rings");
        v.field("ringDimension", ringDimension, {16, 256}, "Ring dimension");
        v.field("maxLayers", maxLayers, {1, 16}, "Max layers");
    }
};

}  // namespace firmament
