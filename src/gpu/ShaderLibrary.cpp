#include "gpu/ShaderLibrary.h"

#include "core/Error.h"
#include "core/Log.h"
#include "gpu/Hresult.h"
#include "gpu/ShaderIncludes.h"

#include <windows.h>

namespace firmament {

ShaderLibrary::ShaderLibrary(ID3D11Device* device, std::unique_ptr<ShaderCompiler> startup)
    : device_(device), startup_(std::move(startup)) {}

std::string ShaderLibrary::techniqueOf(const ShaderKey& key) {
    const auto slash = key.file.find('/');
    return slash == std::string::npos ? std::string("(root)") : key.file.substr(0, slash);
}

ComPtr<ID3D11DeviceChild> ShaderLibrary::createShader(const ShaderKey& key, const std::vector<std::uint8_t>& bytecode) {
    const void* code = bytecode.data();
    const SIZE_T size = bytecode.size();
    const std::string what = "creating shader " + key.id();
    switch (key.stage()) {
        case ShaderStage::Vertex: {
            ComPtr<ID3D11VertexShader> s;
            check(device_->CreateVertexShader(code, size, nullptr, &s), what);
            return s;
        }
        case ShaderStage::Pixel: {
            ComPtr<ID3D11PixelShader> s;
            check(device_->CreatePixelShader(code, size, nullptr, &s), what);
            return s;
        }
        case ShaderStage::Compute: {
            ComPtr<ID3D11ComputeShader> s;
            check(device_->CreateComputeShader(code, size, nullptr, &s), what);
            return s;
        }
        case ShaderStage::Geometry: {
            ComPtr<ID3D11GeometryShader> s;
            check(device_->CreateGeometryShader(code, size, nullptr, &s), what);
            return s;
        }
        default: throw Error("shader " + key.id() + ": hull and domain shaders are not used yet");
    }
}

ShaderLibrary::Entry& ShaderLibrary::load(const ShaderKey& key, ShaderStage expected) {
    const std::string id = key.id();
    if (auto it = shaders_.find(id); it != shaders_.end()) return it->second;
    if (key.stage() != expected) throw Error("shader " + id + " requested as the wrong stage");

    // A technique that was reloaded runs its edited source: a new permutation of it must be
    // compiled from the same source, not taken from the (older) precompiled set.
    CompileResult compiled;
    const std::string technique = techniqueOf(key);
    if (source_ && reloadedTechniques_.count(technique)) {
        compiled = source_->compile(key);
        if (!compiled.ok) {
            errors_[technique] = key.id() + ":\n" + compiled.log;
            log::error("shader " + id + " (" + source_->name() + "):\n" + compiled.log + "\nusing the precompiled version");
        }
    }
    if (!compiled.ok) compiled = startup_->compile(key);
    if (!compiled.ok) throw Error("shader " + id + " (" + startup_->name() + "): " + compiled.log);

    Entry entry{key, std::move(compiled.bytecode), nullptr};
    entry.shader = createShader(key, entry.bytecode);
    auto& stored = shaders_.emplace(id, std::move(entry)).first->second;
    if (source_) watchSources(key);
    return stored;
}

void ShaderLibrary::watchSources(const ShaderKey& key) {
    for (const std::string& file : shaderSourceFiles(sourceRoot_, key.file)) {
        const auto path = sourceRoot_ / file;
        techniquesOfFile_[path].insert(techniqueOf(key));
        watcher_.watch(path);
    }
}

void ShaderLibrary::enableHotReload(std::unique_ptr<ShaderCompiler> source, std::filesystem::path sourceRoot) {
    source_ = std::move(source);
    sourceRoot_ = std::move(sourceRoot);
    if (!source_) return;
    for (const auto& [id, entry] : shaders_) watchSources(entry.key);
}

ReloadResult ShaderLibrary::reload(const std::set<std::string>& techniques) {
    ReloadResult result;
    if (!source_) return result;
    LARGE_INTEGER start, end, frequency;
    QueryPerformanceCounter(&start);
    for (const std::string& technique : techniques) {
        // Compile every permutation of the technique first; replace them only if all succeed.
        std::vector<std::pair<std::string, Entry>> fresh;
        std::string failure;
        for (const auto& [id, entry] : shaders_) {
            if (techniqueOf(entry.key) != technique) continue;
            CompileResult compiled = source_->compile(entry.key);
            ++result.shadersCompiled;
            if (compiled.ok) {
                try {
                    Entry next{entry.key, std::move(compiled.bytecode), nullptr};
                    next.shader = createShader(entry.key, next.bytecode);
                    fresh.emplace_back(id, std::move(next));
                    continue;
                } catch (const Error& e) {
                    compiled.log = e.what();
                }
            }
            failure += id + ":\n" + compiled.log + (compiled.log.empty() || compiled.log.back() == '\n' ? "" : "\n");
        }
        if (!failure.empty()) {
            errors_[technique] = failure;
            result.failedTechniques.push_back(technique);
            log::error("shader reload of '" + technique + "' failed; the previous shaders stay in use:\n" + failure);
            continue;
        }
        for (auto& [id, entry] : fresh) shaders_[id] = std::move(entry);
        errors_.erase(technique);
        reloadedTechniques_.insert(technique);
        ++result.techniquesReloaded;
        for (const auto& [id, entry] : shaders_)
            if (techniqueOf(entry.key) == technique) watchSources(entry.key);  // includes may have been added
    }
    QueryPerformanceCounter(&end);
    QueryPerformanceFrequency(&frequency);
    result.milliseconds = 1000.0 * static_cast<double>(end.QuadPart - start.QuadPart) / static_cast<double>(frequency.QuadPart);
    if (result.techniquesReloaded)
        log::info("shaders reloaded: " + std::to_string(result.techniquesReloaded) + " technique(s), " +
                  std::to_string(result.shadersCompiled) + " permutation(s) compiled in " +
                  std::to_string(static_cast<int>(result.milliseconds)) + " ms with " + source_->name());
    return result;
}

ReloadResult ShaderLibrary::reloadAll() {
    watcher_.poll();  // what changed is covered by this reload
    std::set<std::string> techniques;
    for (const auto& [id, entry] : shaders_) techniques.insert(techniqueOf(entry.key));
    return reload(techniques);
}

ReloadResult ShaderLibrary::reloadChanged() {
    if (!source_) return {};
    std::set<std::string> techniques;
    for (const auto& file : watcher_.poll()) {
        log::info("shader source changed: " + file.string());
        const auto it = techniquesOfFile_.find(file);
        if (it != techniquesOfFile_.end()) techniques.insert(it->second.begin(), it->second.end());
    }
    return techniques.empty() ? ReloadResult{} : reload(techniques);
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
