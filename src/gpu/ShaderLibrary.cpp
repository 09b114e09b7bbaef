#include "gpu/ShaderLibrary.h"

#include "core/Error.h"
#include "core/Log.h"
#include "gpu/Hresult.h"
#include "gpu/ShaderIncludes.h"

#include <windows.h>

#include <chrono>

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

namespace {

double millisecondsSince(const LARGE_INTEGER& start) {
    LARGE_INTEGER end, frequency;
    QueryPerformanceCounter(&end);
    QueryPerformanceFrequency(&frequency);
    return 1000.0 * static_cast<double>(end.QuadPart - start.QuadPart) / static_cast<double>(frequency.QuadPart);
}

std::string withNewline(const std::string& text) { return text.empty() || text.back() == '\n' ? text : text + "\n"; }

}  // namespace

ShaderLibrary::Entry& ShaderLibrary::load(const ShaderKey& key, ShaderStage expected) {
    const std::string id = key.id();
    if (auto it = shaders_.find(id); it != shaders_.end()) {
        it->second.lastUsedFrame = frame_;
        return it->second;
    }
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

    Entry entry{key, std::move(compiled.bytecode), nullptr, frame_};
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
    // A reload still compiling in the background lands first: this one supersedes it.
    waitForBackgroundCompile();
    LARGE_INTEGER start;
    QueryPerformanceCounter(&start);

    // The permutations the last frames drew come first; the rest of each technique waits.
    std::vector<ShaderKey> inUse, later;
    for (const auto& [id, entry] : shaders_) {
        if (!techniques.count(techniqueOf(entry.key))) continue;
        (entry.lastUsedFrame + 1 >= frame_ ? inUse : later).push_back(entry.key);
    }
    std::vector<CompileResult> compiled = source_->compileAll(inUse);
    result.shadersCompiled = static_cast<int>(inUse.size());

    // Per technique, all of its permutations in use are replaced, or none is.
    std::map<std::string, std::string> failures;
    std::map<std::string, std::vector<Entry>> fresh;  // technique -> its new permutations
    for (size_t i = 0; i < inUse.size(); ++i) {
        const ShaderKey& key = inUse[i];
        CompileResult& c = compiled[i];
        if (c.ok) {
            try {
                Entry next{key, std::move(c.bytecode), nullptr, shaders_.at(key.id()).lastUsedFrame};
                next.shader = createShader(key, next.bytecode);
                fresh[techniqueOf(key)].push_back(std::move(next));
                continue;
            } catch (const Error& e) {
                c.log = e.what();
            }
        }
        failures[techniqueOf(key)] += key.id() + ":\n" + withNewline(c.log);
    }
    std::vector<ShaderKey> background;
    for (const std::string& technique : techniques) {
        if (const auto failed = failures.find(technique); failed != failures.end()) {
            errors_[technique] = failed->second;
            result.failedTechniques.push_back(technique);
            log::error("shader reload of '" + technique + "' failed; the previous shaders stay in use:\n" + failed->second);
            continue;
        }
        bool any = false;
        for (Entry& entry : fresh[technique]) {
            watchSources(entry.key);  // includes may have been added
            const std::string id = entry.key.id();
            shaders_[id] = std::move(entry);
            any = true;
        }
        // The technique's other permutations are stale now: a request before the background
        // compile lands compiles it from the edited source (load()).
        for (const ShaderKey& key : later)
            if (techniqueOf(key) == technique) {
                shaders_.erase(key.id());
                background.push_back(key);
                any = true;
            }
        if (!any) continue;
        errors_.erase(technique);
        reloadedTechniques_.insert(technique);
        ++result.techniquesReloaded;
    }
    result.milliseconds = millisecondsSince(start);
    result.shadersInBackground = static_cast<int>(background.size());
    if (!background.empty()) {
        background_ = std::async(std::launch::async, [compiler = source_.get(), keys = std::move(background)]() mutable {
            LARGE_INTEGER begun;
            QueryPerformanceCounter(&begun);
            Background done;
            done.results = compiler->compileAll(keys);
            done.keys = std::move(keys);
            done.milliseconds = millisecondsSince(begun);
            return done;
        });
    }
    if (result.techniquesReloaded)
        log::info("shaders reloaded: " + std::to_string(result.techniquesReloaded) + " technique(s), " +
                  std::to_string(result.shadersCompiled) + " permutation(s) in use compiled in " +
                  std::to_string(static_cast<int>(result.milliseconds)) + " ms with " + source_->name() +
                  (result.shadersInBackground ? ", " + std::to_string(result.shadersInBackground) + " more in the background" : ""));
    return result;
}

void ShaderLibrary::beginFrame() {
    ++frame_;
    if (background_.valid() && background_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) collectBackground();
}

void ShaderLibrary::waitForBackgroundCompile() {
    if (background_.valid()) collectBackground();
}

void ShaderLibrary::collectBackground() {
    Background done = background_.get();
    int swapped = 0;
    std::map<std::string, std::string> failures;
    for (size_t i = 0; i < done.keys.size(); ++i) {
        const ShaderKey& key = done.keys[i];
        CompileResult& c = done.results[i];
        if (shaders_.count(key.id())) continue;  // asked for meanwhile, and compiled then
        if (c.ok) {
            try {
                Entry entry{key, std::move(c.bytecode), nullptr, 0};
                entry.shader = createShader(key, entry.bytecode);
                shaders_.emplace(key.id(), std::move(entry));
                watchSources(key);
                ++swapped;
                continue;
            } catch (const Error& e) {
                c.log = e.what();
            }
        }
        // Left out: if it is asked for, load() tries the source again, then the precompiled one.
        failures[techniqueOf(key)] += key.id() + ":\n" + withNewline(c.log);
    }
    for (const auto& [technique, failure] : failures) {
        errors_[technique] = failure;
        log::error("shader reload of '" + technique + "' failed in the background for permutations not in use:\n" + failure);
    }
    log::info("shaders reloaded in the background: " + std::to_string(swapped) + " of " + std::to_string(done.keys.size()) +
              " permutation(s) in " + std::to_string(static_cast<int>(done.milliseconds)) + " ms");
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
