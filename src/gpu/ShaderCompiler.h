#pragma once
// Where shader bytecode comes from. One interface for every backend: the DXBC compiled at
// build time (PrecompiledShaders), and, for hot reload, D3DCompile or an external compiler
// process that compile the HLSL on disk.
#include "gpu/ShaderKey.h"

#include <cstdint>
#include <string>
#include <vector>

namespace firmament {

struct CompileResult {
    bool ok = false;
    std::vector<std::uint8_t> bytecode;  // DXBC
    std::string log;                     // the compiler's messages (errors when !ok)
};

class ShaderCompiler {
public:
    virtual ~ShaderCompiler() = default;
    virtual std::string name() const = 0;
    virtual CompileResult compile(const ShaderKey& key) = 0;
};

}  // namespace firmament
