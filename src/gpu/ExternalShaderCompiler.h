#pragma once
// Compiles HLSL from the shader source folder with a compiler program:
//  - vkd3d-compiler on the Linux host, when running under Wine (the build's compiler, so
//    reloaded shaders match the precompiled ones exactly). It takes no -D or -I, so a
//    wrapper file holds the defines and includes the source, and it runs in the shader
//    root, where #include paths start;
//    Several permutations are compiled by one host command that runs the compiler on every
//    core at once (xargs -P): under Wine, starting a host process costs far more than
//    compiling a shader. With the build's cmake/shader-cache.sh named, each goes through the
//    build's cache of compiled shaders, so an unedited permutation costs a file copy;
//  - fxc.exe from the Windows SDK, with /D and /I, a process per permutation on each core.
#include "gpu/ShaderCompiler.h"

#include <filesystem>

namespace firmament {

enum class ExternalCompilerKind { Vkd3dOnHost, Fxc };

class ExternalShaderCompiler final : public ShaderCompiler {
public:
    // `program`: the compiler (a host path for vkd3d, a Windows path for fxc). Throws Error
    // when the kind cannot run here (vkd3d outside Wine).
    // `cacheLauncher`: the host path of the build's shader-cache.sh (vkd3d only; empty: none).
    ExternalShaderCompiler(ExternalCompilerKind kind, std::filesystem::path program, std::filesystem::path root,
                           std::string cacheLauncher = {});

    std::string name() const override;
    CompileResult compile(const ShaderKey& key) override;
    std::vector<CompileResult> compileAll(const std::vector<ShaderKey>& keys) override;

private:
    CompileResult compileWithFxc(const ShaderKey& key);
    std::vector<CompileResult> compileAllOnHost(const std::vector<ShaderKey>& keys);

    ExternalCompilerKind kind_;
    std::filesystem::path program_;
    std::filesystem::path root_;
    std::string cacheLauncher_;
    std::filesystem::path scratch_;  // wrappers, outputs and logs of runs in flight
};

// The pieces, pure so that they are unit-tested.
std::string vkd3dWrapperSource(const ShaderKey& key);
// One permutation's command, through the cache launcher when one is given.
std::string vkd3dShellCommand(const std::string& compiler, const std::string& root, const ShaderKey& key,
                              const std::string& wrapper, const std::string& output, const std::string& cacheLauncher = {});
// Runs each job script (a host path) once, as many at a time as the host has cores.
std::string parallelJobsCommand(const std::vector<std::string>& jobScripts);
std::wstring fxcCommandLine(const std::filesystem::path& fxc, const std::filesystem::path& root, const ShaderKey& key,
                            const std::filesystem::path& output);

}  // namespace firmament
