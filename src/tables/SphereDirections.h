#pragma once
// The quadrature points of the tables' integrals over the sphere of directions (Yusov 2013,
// eq. 1 and 3; Bruneton and Neyret 2008, eq. 7 and the irradiance integral).
#include <d3d11.h>
#include <glm/glm.hpp>
#include <wrl/client.h>

#include <vector>

namespace firmament {

// `count` directions spread evenly over the unit sphere (a spherical Fibonacci set: equal
// areas, y from 1 - 1/count down to -1 + 1/count).
std::vector<glm::vec4> uniformSphereDirections(int count);
// The same as a structured buffer of float4 for the shaders.
Microsoft::WRL::ComPtr<ID3D11ShaderResourceView> createSphereDirectionsView(ID3D11Device* device, int count);

}  // namespace firmament
