#pragma once
// Yusov 2013's tables as a second technique reads them: the light shafts compute the light
// scattered along each ray themselves, and look it up in these tables. Everything the look-up
// functions of shaders/atmosphere/yusov/lookup.hlsli and aerial_perspective.hlsli take: the
// physical constants with the tables' sizes (the parameterization's inputs), the tables, their
// sampler, the render modes and the sun's disc. Nothing of the atmosphere's internals.
#include "frame/ScatteringModes.h"

#include <d3d11.h>

namespace firmament {

struct ScatteringLookup {
    bool ready = false;                                        // false until the tables exist
    ID3D11Buffer* atmosphere = nullptr;                        // AtmosphereConstants
    ID3D11ShaderResourceView* netDensity = nullptr;            // Texture2D: optical depth to the top, by altitude and zenith cosine
    ID3D11ShaderResourceView* singleScattering = nullptr;      // Texture3D: L^(1), 4D packed, by species (lookUpSpeciesScattering)
    ID3D11ShaderResourceView* highOrderScattering = nullptr;   // Texture3D: L^(2) + ... + L^(N), radiance
    ID3D11ShaderResourceView* multipleScattering = nullptr;    // Texture3D: L^(1) + high orders, by species
    ID3D11ShaderResourceView* ambientLight = nullptr;          // Texture2D, N x 1: sky irradiance by sun zenith cosine
    ID3D11SamplerState* linearClamp = nullptr;                 // the sampler every look-up uses
    SingleScatteringMode singleMode = SingleScatteringMode::Table;          // the settings' render modes
    MultipleScatteringMode multipleMode = MultipleScatteringMode::Unoccluded;
    int integrationSteps = 30;
    float sunCosAngularRadius = 0.0f;  // the sun's disc
    float sunDiscRadiance = 0.0f;      // per unit irradiance
};

}  // namespace firmament
