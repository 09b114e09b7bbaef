#pragma once
// What both models' pre-computation shaders read besides their tables: the physical constants
// (b0), the unit of work's range of slices or layers (the last constant buffer), the sampler of
// every table look-up (s0), and the quadrature directions of the integrals over the sphere.
#include "gpu/ConstantBuffer.h"
#include "atmosphere/AtmosphereStructures.h"

#include <d3d11.h>
#include <wrl/client.h>

namespace firmament {

class AtmosphereComputeInputs {
public:
    AtmosphereComputeInputs(ID3D11Device* device, int sphereSamples);

    // Binds, for the compute stage, `constants` at b0, `modelConstants` (when given) at b1, the
    // unit's [first, end) after them, and the sampler at s0.
    void bind(ID3D11DeviceContext* context, const gpu::AtmosphereConstants& constants, ID3D11Buffer* modelConstants, unsigned first,
              unsigned end);
    ID3D11ShaderResourceView* sphereDirections() const { return sphereDirections_.Get(); }

private:
    Microsoft::WRL::ComPtr<ID3D11ShaderResourceView> sphereDirections_;
    ConstantBuffer<gpu::AtmosphereConstants> atmosphere_;
    ConstantBuffer<gpu::PrecomputeSliceConstants> slab_;
    Microsoft::WRL::ComPtr<ID3D11SamplerState> linearClamp_;
};

}  // namespace firmament
