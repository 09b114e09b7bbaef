#pragma once
// What both atmosphere models' pre-computations share: the sampler of every table look-up,
// the equal-area directions of their sphere integrals, and running all remaining units of
// work with progress in the log.
#include "gpu/Texture.h"

#include <glm/glm.hpp>

#include <functional>
#include <string>
#include <vector>

namespace firmament {

// The sampler every look-up into the tables uses.
ComPtr<ID3D11SamplerState> createLinearClampSampler(ID3D11Device* device);

// `count` directions spread evenly over the unit sphere (a spherical Fibonacci set: equal
// areas, y from 1 - 1/count down to -1 + 1/count): the quadrature points of the integrals over
// the sphere (document 000's eq. 1 and 3; document 002's eq. 7 and the irradiance integral).
std::vector<glm::vec4> uniformSphereDirections(int count);
// The same as a structured buffer of float4 for the shaders.
ComPtr<ID3D11ShaderResourceView> createSphereDirectionsView(ID3D11Device* device, int count);

// Work cut into units; runAllUnits() runs what is left, logging every 10% of progress with
// the next stage's name, then waits for the GPU and logs the time taken.
struct UnitsOfWork {
    std::function<bool()> step;              // runs the next unit; false when none was left
    std::function<double()> progress;        // 0..1
    std::function<std::string()> nextStage;  // what the next unit does
};
void runAllUnits(ID3D11DeviceContext* context, const std::string& logPrefix, const UnitsOfWork& work);

// Blocks until the GPU has finished the work submitted so far.
void waitForGpu(ID3D11DeviceContext* context);

}  // namespace firmament
