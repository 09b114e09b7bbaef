#pragma once
// Bruneton and Neyret 2008's tables as a second technique reads them (the clouds light their
// particles and find the air between the camera and them with these): the physical constants,
// the model's own constants, the transmittance, irradiance and in-scatter tables and their
// sampler, for the look-up functions of shaders/atmosphere/bruneton/lookup.hlsli and
// camera_segment.hlsli. Nothing of the atmosphere's internals.
#include <d3d11.h>

namespace firmament {

struct BrunetonLookup {
    bool ready = false;                                  // false until the tables exist
    ID3D11Buffer* atmosphere = nullptr;                  // AtmosphereConstants
    ID3D11Buffer* bruneton = nullptr;                    // BrunetonConstants
    ID3D11ShaderResourceView* transmittance = nullptr;   // Texture2D: to the top of the atmosphere
    ID3D11ShaderResourceView* irradiance = nullptr;      // Texture2D: the sky's irradiance
    ID3D11ShaderResourceView* inscatter = nullptr;       // Texture3D: S, 4D packed
    ID3D11SamplerState* linearClamp = nullptr;
};

}  // namespace firmament
