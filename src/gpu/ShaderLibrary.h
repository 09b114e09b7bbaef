#pragma once
// Owns every shader object the techniques use, created on first request and cached by the
// permutation's key. Techniques ask for their shaders by key each time they draw, so a
// later reload can replace entries without the techniques holding stale pointers.
#include "gpu/ShaderCompiler.h"
#include "gpu/ShaderKey.h"

#include <d3d11.h>
#include <wrl/client.h>

#include <memory>
#include <unordered_map>

namespace firmament {

using Microsoft::WRL::ComPtr;

class ShaderLibrary {
public:
    ShaderLibrary(ID3D11Device* device, std::unique_ptr<ShaderCompiler> compiler);

    ID3D11VertexShader* vertexShader(const ShaderKey& key);
    ID3D11PixelShader* pixelShader(const ShaderKey& key);
    ID3D11ComputeShader* computeShader(const ShaderKey& key);
    ID3D11GeometryShader* geometryShader(const ShaderKey& key);

    // Bytecode of a loaded permutation (input layouts are validated against it).
    const std::vector<std::uint8_t>& bytecode(const ShaderKey& key);

    const ShaderCompiler& compiler() const { return *compiler_; }
    size_t size() const { return shaders_.size(); }

private:
    struct Entry {
        std::vector<std::uint8_t> bytecode;
        ComPtr<ID3D11DeviceChild> shader;  // the stage's shader interface
    };
    Entry& load(const ShaderKey& key, ShaderStage expected);  // throws Error with the compiler's log

    ID3D11Device* device_;
    std::unique_ptr<ShaderCompiler> compiler_;
    std::unordered_map<std::string, Entry> shaders_;
};

}  // namespace firmament
