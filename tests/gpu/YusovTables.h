#pragma once
// Yusov 2013's tables computed at once on the test's device, for the suites that hold them to the
// reference (AtmosphereLutTest) or to Bruneton and Neyret 2008's (BrunetonTablesTest).
#include "atmosphere/AtmosphereParameters.h"
#include "atmosphere/yusov/YusovPrecomputation.h"
#include "atmosphere/yusov/YusovTableFiles.h"
#include "gpu/ShaderLibrary.h"

#include <d3d11.h>

#include <filesystem>
#include <memory>
#include <string>

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

// The same, for a suite whose tests read the same tables: the first test that asks computes them
// and writes them into `folder`, as the program's cache does; the others load them from there
// (AtmosphereTables.TableFilesRoundTripAndRefuseBadFiles holds the files to the tables bit for
// bit). The suite empties `folder` before its first test, so each run computes them once.
inline std::unique_ptr<YusovPrecomputation> computeOrLoadYusovTables(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders,
                                                                     LutResolution resolution, int orders, const std::filesystem::path& folder) {
    AtmosphereParameters p;
    p.lut = LutDimensions::of(resolution);
    p.scatteringOrders = orders;
    auto tables = std::make_unique<YusovPrecomputation>(device, p);
    const std::string key = yusovTableKey(p, shaders);
    if (readTables(context, *tables, key, folder, key + "-").empty()) return tables;
    tables->runAll(context, shaders);
    writeTables(device, context, *tables, key, folder, key + "-");
    return tables;
}

}  // namespace firmament::test
