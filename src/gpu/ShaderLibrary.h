#pragma once
// Owns every shader object the techniques use, created on first request and cached by the
// permutation's key. Techniques ask for their shaders by key each time they draw, so a
// reload can replace entries without the techniques holding stale pointers.
//
// Hot reload: with a source compiler (D3DCompile, vkd3d-compiler, fxc) the library recompiles
// from the HLSL folder on request (F8) and when a source file or any file it includes
// changes on disk. Shaders are reloaded per technique, the first folder of their file
// ("postfx/tone_mapping.hlsl" belongs to "postfx"). The permutations in use (drawn this
// frame or the last) are compiled first, all at once, and replaced together, or, if one fails
// to compile, none is, and the compiler's message stays in errors() until a later reload of
// that technique succeeds. The technique's other loaded permutations are then compiled in the
// background and swapped in at a later frame; one asked for before that is compiled from the
// edited source when asked for, and one that fails falls back to its precompiled version,
// its message in errors().
#include "core/FileWatcher.h"
#include "gpu/ShaderCompiler.h"
#include "gpu/ShaderKey.h"

#include <d3d11.h>
#include <wrl/client.h>

#include <cstdint>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <set>
#include <unordered_map>

namespace firmament {

using Microsoft::WRL::ComPtr;

struct ReloadResult {
    int techniquesReloaded = 0;
    int shadersCompiled = 0;  // the permutations in use, compiled before the reload returned
    int shadersInBackground = 0;  // the techniques' other permutations, compiled after it
    std::vector<std::string> failedTechniques;
    double milliseconds = 0.0;

    bool attempted() const { return techniquesReloaded > 0 || !failedTechniques.empty(); }
};

class ShaderLibrary {
public:
    // `startup` provides the first version of every shader (the build's precompiled DXBC).
    ShaderLibrary(ID3D11Device* device, std::unique_ptr<ShaderCompiler> startup);

    ID3D11VertexShader* vertexShader(const ShaderKey& key);
    ID3D11PixelShader* pixelShader(const ShaderKey& key);
    ID3D11ComputeShader* computeShader(const ShaderKey& key);
    ID3D11GeometryShader* geometryShader(const ShaderKey& key);

    // Bytecode of a loaded permutation (input layouts are validated against it).
    const std::vector<std::uint8_t>& bytecode(const ShaderKey& key);

    // Turns hot reload on: `source` compiles the HLSL under `sourceRoot`.
    void enableHotReload(std::unique_ptr<ShaderCompiler> source, std::filesystem::path sourceRoot);
    bool hotReloadEnabled() const { return source_ != nullptr; }
    const ShaderCompiler* sourceCompiler() const { return source_.get(); }
    const std::filesystem::path& sourceRoot() const { return sourceRoot_; }

    ReloadResult reloadAll();      // F8: every loaded technique
    ReloadResult reloadChanged();  // only techniques whose files changed on disk since the last call

    // Called once a frame, before drawing: what the frame asks for is "in use", and the
    // permutations compiled in the background since the last frame are swapped in.
    void beginFrame();
    bool backgroundCompilePending() const { return background_.valid(); }
    void waitForBackgroundCompile();  // blocks until the background permutations are in

    // Technique -> the compiler's message of its last failed reload.
    const std::map<std::string, std::string>& errors() const { return errors_; }

    static std::string techniqueOf(const ShaderKey& key);

    const ShaderCompiler& compiler() const { return *startup_; }
    size_t size() const { return shaders_.size(); }

private:
    struct Entry {
        ShaderKey key;
        std::vector<std::uint8_t> bytecode;
        ComPtr<ID3D11DeviceChild> shader;  // the stage's shader interface
        std::uint64_t lastUsedFrame = 0;
    };
    struct Background {
        std::vector<ShaderKey> keys;
        std::vector<CompileResult> results;
        double milliseconds = 0.0;
    };
    Entry& load(const ShaderKey& key, ShaderStage expected);  // throws Error with the compiler's log
    ComPtr<ID3D11DeviceChild> createShader(const ShaderKey& key, const std::vector<std::uint8_t>& bytecode);
    void watchSources(const ShaderKey& key);
    ReloadResult reload(const std::set<std::string>& techniques);
    void collectBackground();  // swaps in the finished background compile

    ID3D11Device* device_;
    std::unique_ptr<ShaderCompiler> startup_;
    std::unique_ptr<ShaderCompiler> source_;
    std::filesystem::path sourceRoot_;
    std::unordered_map<std::string, Entry> shaders_;
    std::map<std::filesystem::path, std::set<std::string>> techniquesOfFile_;
    std::set<std::string> reloadedTechniques_;  // their new permutations compile from source too
    std::map<std::string, std::string> errors_;
    FileWatcher watcher_;
    std::uint64_t frame_ = 0;
    // Declared last: destroyed first, so that a compile in flight ends before source_ does.
    std::future<Background> background_;
};

}  // namespace firmament
