#include "gpu/ExternalShaderCompiler.h"

#include "core/ChildProcess.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Text.h"

#include <windows.h>

#include <atomic>

namespace firmament {

namespace {

constexpr int kCompileTimeoutMs = 60'000;

std::wstring quoteWindowsArgument(const std::wstring& argument) {
    if (!argument.empty() && argument.find_first_of(L" \t\"") == std::wstring::npos) return argument;
    std::wstring quoted = L"\"";
    for (wchar_t c : argument) quoted += c == L'"' ? std::wstring(L"\\\"") : std::wstring(1, c);
    return quoted + L"\"";
}

std::filesystem::path scratchFolder() {
    wchar_t temp[MAX_PATH];
    const DWORD length = GetTempPathW(MAX_PATH, temp);
    auto folder = std::filesystem::path(std::wstring(temp, length)) / ("firmament-shaders-" + std::to_string(GetCurrentProcessId()));
    std::filesystem::create_directories(folder);
    return folder;
}

}  // namespace

std::string vkd3dWrapperSource(const ShaderKey& key) {
    std::string text = "// Firmament hot reload: " + key.id() + "\n";
    for (const std::string& define : key.defines) {
        const auto eq = define.find('=');
        text += "#define " + define.substr(0, eq) + " " + (eq == std::string::npos ? "1" : define.substr(eq + 1)) + "\n";
    }
    return text + "#include \"" + key.file + "\"\n";
}

std::string vkd3dShellCommand(const std::string& compiler, const std::string& root, const ShaderKey& key,
                              const std::string& wrapper, const std::string& output) {
    return "cd " + shellQuote(root) + " && " + shellQuote(compiler) + " -x hlsl -b dxbc-tpf -p " + shellQuote(key.profile) +
           " -e " + shellQuote(key.entry) + " -o " + shellQuote(output) + " " + shellQuote(wrapper);
}

std::wstring fxcCommandLine(const std::filesystem::path& fxc, const std::filesystem::path& root, const ShaderKey& key,
                            const std::filesystem::path& output) {
    std::wstring line = quoteWindowsArgument(fxc.wstring()) + L" /nologo /O3 /T " + widen(key.profile) + L" /E " +
                        widen(key.entry) + L" /I " + quoteWindowsArgument(root.wstring());
    for (const std::string& define : key.defines) line += L" /D " + quoteWindowsArgument(widen(define));
    return line + L" /Fo " + quoteWindowsArgument(output.wstring()) + L" " + quoteWindowsArgument((root / key.file).wstring());
}

ExternalShaderCompiler::ExternalShaderCompiler(ExternalCompilerKind kind, std::filesystem::path program, std::filesystem::path root)
    : kind_(kind), program_(std::move(program)), root_(std::move(root)), scratch_(scratchFolder()) {
    if (kind_ == ExternalCompilerKind::Vkd3dOnHost && !runningUnderWine())
        throw Error("the vkd3d shader compiler backend runs only under Wine; use d3dcompile or fxc on Windows");
}

std::string ExternalShaderCompiler::name() const {
    return (kind_ == ExternalCompilerKind::Fxc ? "fxc (" : "vkd3d-compiler on the host (") + program_.string() + ")";
}

CompileResult ExternalShaderCompiler::compile(const ShaderKey& key) {
    static std::atomic<unsigned> counter{0};
    const std::string stem = "shader-" + std::to_string(counter++);
    const auto output = scratch_ / (stem + ".cso");
    std::error_code ec;
    std::filesystem::remove(output, ec);
    CompileResult result;
    try {
        ChildResult run;
        if (kind_ == ExternalCompilerKind::Vkd3dOnHost) {
            const auto wrapper = scratch_ / (stem + ".hlsl");
            const std::string text = vkd3dWrapperSource(key);
            writeFileText(wrapper, text);
            const auto hostRoot = hostPath(root_), hostWrapper = hostPath(wrapper), hostOutput = hostPath(output);
            if (!hostRoot || !hostWrapper || !hostOutput) throw Error("no host path for the shader folders");
            run = runHostShellCommand(vkd3dShellCommand(program_.generic_string(), *hostRoot, key, *hostWrapper, *hostOutput),
                                      scratch_, kCompileTimeoutMs);
            std::filesystem::remove(wrapper, ec);
        } else {
            run = runWindowsProgram(fxcCommandLine(program_, root_, key, output), root_, kCompileTimeoutMs);
        }
        result.log = run.output;
        if (run.exitCode == 0 && std::filesystem::exists(output, ec)) {
            result.bytecode = readFileBytes(output);
            result.ok = !result.bytecode.empty();
        }
        if (!result.ok && result.log.empty()) result.log = "the compiler failed with exit code " + std::to_string(run.exitCode);
    } catch (const Error& e) {
        result.ok = false;
        result.log = e.what();
    }
    std::filesystem::remove(output, ec);
    return result;
}

}  // namespace firmament
