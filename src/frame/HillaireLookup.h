#pragma once
// Hillaire 2020's tables as a second technique reads them (the clouds light their particles and
// march the air between the camera and them with these): the physical constants, the model's own
// constants with the frame's sampling (the steps of a view marched per pixel), the transmittance
// and multiple-scattering tables and Firmament's sky irradiance table for the model, and their
// sampler, for the functions of shaders/atmosphere/hillaire/lookup.hlsli and march.hlsli. Nothing
// of the atmosphere's internals.
#include <d3d11.h>

namespace firmament {

struct HillaireLookup {
    bool ready = false;                                        // false until the tables exist
    ID3D11Buffer* atmosphere = nullptr;                        // AtmosphereConstants
    ID3D11Buffer* hillaire = nullptr;                          // HillaireConstants
    ID3D11ShaderResourceView* transmittance = nullptr;         // Texture2D: to the top of the atmosphere
    ID3D11ShaderResourceView* multipleScattering = nullptr;    // Texture2D: Psi_ms
    ID3D11ShaderResourceView* irradiance = nullptr;            // Texture2D: the sky's irradiance
    ID3D11SamplerState* linearClamp = nullptr;
};

}  // namespace firmament
