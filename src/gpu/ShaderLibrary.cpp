#include "gpu/ShaderLibrary.h"

#include "core/Error.h"
#include "gpu/Hresult.h"

namespace firmament {

ShaderLibrary::ShaderLibrary(ID3D11Device* device, std::unique_ptr<ShaderCompiler> compiler)
    : device_(device), compiler_(std::move(compiler)) {}

ShaderLibrary::Entry& ShaderLibrary::load(const ShaderKey& key, ShaderStage expected) {
    const std::string id = key.id();
    if (auto it = shaders_.find(id); it != shaders_.end()) return it->second;
    if (key.stage() != expected) throw Error("shader " + id + " requested as the wrong stage");

    CompileResult compiled = compiler_->compile(key);
    if (!compiled.ok) throw Error("shader " + id + " (" + compiler_->name() + "): " + compiled.log);

    Entry entry;
    entry.bytecode = std::move(compiled.bytecode);
    const void* code = entry.bytecode.data();
    const SIZE_T size = entry.bytecode.size();
    const std::string what = "creating shader " + id;
    switch (expected) {
        case ShaderStage::Vertex: {
            ComPtr<ID3D11VertexShader> s;
            check(device_->CreateVertexShader(code, size, nullptr, &s), what);
            entry.shader = s;
            break;
        }
        case ShaderStage::Pixel: {
            ComPtr<ID3D11PixelShader> s;
            check(device_->CreatePixelShader(code, size, nullptr, &s), what);
            entry.shader = s;
            break;
        }
        case ShaderStage::Compute: {
            ComPtr<ID3D11ComputeShader> s;
            check(device_->CreateComputeShader(code, size, nullptr, &s), what);
            entry.shader = s;
            break;
        }
        case ShaderStage::Geometry: {
            ComPtr<ID3D11GeometryShader> s;
            check(device_->CreateGeometryShader(code, size, nullptr, &s), what);
            entry.shader = s;
            break;
        }
        default: throw Error("shader " + id + ": hull and domain shaders are not used yet");
    }
    return shaders_.emplace(id, std::move(entry)).first->second;
}

ID3D11VertexShader* ShaderLibrary::vertexShader(const ShaderKey& key) {
    return static_cast<ID3D11VertexShader*>(load(key, ShaderStage::Vertex).shader.Get());
}
ID3D11PixelShader* ShaderLibrary::pixelShader(const ShaderKey& key) {
    return static_cast<ID3D11PixelShader*>(load(key, ShaderStage::Pixel).shader.Get());
}
ID3D11ComputeShader* ShaderLibrary::computeShader(const ShaderKey& key) {
    return static_cast<ID3D11ComputeShader*>(load(key, ShaderStage::Compute).shader.Get());
}
ID3D11GeometryShader* ShaderLibrary::geometryShader(const ShaderKey& key) {
    return static_cast<ID3D11GeometryShader*>(load(key, ShaderStage::Geometry).shader.Get());
}

const std::vector<std::uint8_t>& ShaderLibrary::bytecode(const ShaderKey& key) {
    return load(key, key.stage()).bytecode;
}

}  // namespace firmament
