#include "atmosphere/AtmosphereComputeInputs.h"

#include "gpu/CommonStates.h"
#include "tables/SphereDirections.h"

namespace firmament {

AtmosphereComputeInputs::AtmosphereComputeInputs(ID3D11Device* device, int sphereSamples)
    : sphereDirections_(createSphereDirectionsView(device, sphereSamples)), atmosphere_(device), slab_(device),
      linearClamp_(states::linearClamp(device)) {}

void AtmosphereComputeInputs::bind(ID3D11DeviceContext* context, const gpu::AtmosphereConstants& constants, ID3D11Buffer* modelConstants,
                                   unsigned first, unsigned end) {
    atmosphere_.update(context, constants);
    gpu::PrecomputeSliceConstants slab{};
    slab.range = glm::uvec4(first, end, 0u, 0u);
    slab_.update(context, slab);
    ID3D11Buffer* buffers[3] = {atmosphere_.get(), modelConstants ? modelConstants : slab_.get(), slab_.get()};
    context->CSSetConstantBuffers(0, modelConstants ? 3 : 2, buffers);
    context->CSSetSamplers(0, 1, linearClamp_.GetAddressOf());
}

}  // namespace firmament
