#pragma once
// Yusov 2013's tables computed at once on the test's device, for the suites that hold them to the
// reference (AtmosphereLutTest) or to Bruneton and Neyret 2008's (BrunetonTablesTest).
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/yusov/YusovPrecomputation.h"
#include "gpu/ShaderLibrary.h"

#include <d3d11.h>

#include <memory>

namespace firmament::test {

inline std::unique_ptr<YusovPrecomputation> computeYusovTables(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders,
                                                               LutResolution resolution, int orders) {
    AtmosphereParameters p;
    p.lut = LutDimensions::of(resolution);
    p.scatteringOrders = orders;
    auto tables = std::make_unique<YusovPrecomputation>(device, p);
    tables->runAll(context, shaders);
    return tables;
}

}  // namespace firmament::test
