#include "gpu/ExternalShaderCompiler.h"

#include "core/ChildProcess.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "core/Text.h"

#include <windows.h>

#include <atomic>
#include <cstdlib>
#include <vector>

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

std::string readText(const std::filesystem::path& path) {
    const std::vector<std::uint8_t> bytes = readFileBytes(path);
    return std::string(bytes.begin(), bytes.end());
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
                              const std::string& wrapper, const std::string& output, const std::string& cacheLauncher) {
    const std::string launcher = cacheLauncher.empty() ? std::string() : "sh " + shellQuote(cacheLauncher) + " ";
    return "cd " + shellQuote(root) + " && " + launcher + shellQuote(compiler) + " -x hlsl -b dxbc-tpf -p " +
           shellQuote(key.profile) + " -e " + shellQuote(key.entry) + " -o " + shellQuote(output) + " " + shellQuote(wrapper);
}

std::string parallelJobsCommand(const std::vector<std::string>& jobScripts) {
    std::string command = "printf '%s\\n'";
    for (const std::string& job : jobScripts) command += " " + shellQuote(job);
    return command + " | xargs -P \"$(nproc 2>/dev/null || echo 2)\" -n 1 sh";
}

std::wstring fxcCommandLine(const std::filesystem::path& fxc, const std::filesystem::path& root, const ShaderKey& key,
                            const std::filesystem::path& output) {
    std::wstring line = quoteWindowsArgument(fxc.wstring()) + L" /nologo /O3 /T " + widen(key.profile) + L" /E " +
                        widen(key.entry) + L" /I " + quoteWindowsArgument(root.wstring());
    for (const std::string& define : key.defines) line += L" /D " + quoteWindowsArgument(widen(define));
    return line + L" /Fo " + quoteWindowsArgument(output.wstring()) + L" " + quoteWindowsArgument((root / key.file).wstring());
}

ExternalShaderCompiler::ExternalShaderCompiler(ExternalCompilerKind kind, std::filesystem::path program, std::filesystem::path root,
                                               std::string cacheLauncher)
    : kind_(kind), program_(std::move(program)), root_(std::move(root)), cacheLauncher_(std::move(cacheLauncher)), scratch_(scratchFolder()) {
    if (kind_ == ExternalCompilerKind::Vkd3dOnHost && !runningUnderWine())
        throw Error("the vkd3d shader compiler backend runs only under Wine; use d3dcompile or fxc on Windows");
}

std::string ExternalShaderCompiler::name() const {
    if (kind_ == ExternalCompilerKind::Fxc) return "fxc (" + program_.string() + ")";
    return "vkd3d-compiler on the host (" + program_.string() + (cacheLauncher_.empty() ? "" : ", through the build's shader cache") + ")";
}

CompileResult ExternalShaderCompiler::compile(const ShaderKey& key) {
    return kind_ == ExternalCompilerKind::Fxc ? compileWithFxc(key) : compileAllOnHost({key}).front();
}

std::vector<CompileResult> ExternalShaderCompiler::compileAll(const std::vector<ShaderKey>& keys) {
    if (kind_ == ExternalCompilerKind::Fxc) return ShaderCompiler::compileAll(keys);  // a process per shader, on each core
    return keys.empty() ? std::vector<CompileResult>{} : compileAllOnHost(keys);
}

CompileResult ExternalShaderCompiler::compileWithFxc(const ShaderKey& key) {
    static std::atomic<unsigned> counter{0};
    const auto output = scratch_ / ("shader-" + std::to_string(counter++) + ".cso");
    std::error_code ec;
    std::filesystem::remove(output, ec);
    CompileResult result;
    try {
        const ChildResult run = runWindowsProgram(fxcCommandLine(program_, root_, key, output), root_, kCompileTimeoutMs);
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

// Every permutation gets a wrapper (its defines, then the source), a job script that compiles
// it and writes the compiler's messages and exit status beside it, and one host command runs
// the jobs on every core.
std::vector<CompileResult> ExternalShaderCompiler::compileAllOnHost(const std::vector<ShaderKey>& keys) {
    static std::atomic<unsigned> counter{0};
    struct Job {
        std::filesystem::path wrapper, output, script, log, status;
    };
    std::vector<Job> jobs;
    std::vector<CompileResult> results(keys.size());
    std::error_code ec;
    try {
        const auto hostRoot = hostPath(root_);
        if (!hostRoot) throw Error("no host path for the shader folder " + root_.string());
        std::vector<std::string> hostScripts;
        for (const ShaderKey& key : keys) {
            const std::string stem = "shader-" + std::to_string(counter++);
            Job job{scratch_ / (stem + ".hlsl"), scratch_ / (stem + ".cso"), scratch_ / (stem + ".sh"), scratch_ / (stem + ".log"),
                    scratch_ / (stem + ".status")};
            jobs.push_back(job);
            const auto hostWrapper = hostPath(job.wrapper), hostOutput = hostPath(job.output), hostLog = hostPath(job.log),
                       hostStatus = hostPath(job.status), hostScript = hostPath(job.script);
            if (!hostWrapper || !hostOutput || !hostLog || !hostStatus || !hostScript) throw Error("no host path for the shader scratch folder");
            writeFileText(job.wrapper, vkd3dWrapperSource(key));
            writeFileText(job.script, "(" + vkd3dShellCommand(program_.generic_string(), *hostRoot, key, *hostWrapper, *hostOutput, cacheLauncher_) +
                                          ") >" + shellQuote(*hostLog) + " 2>&1\necho $? >" + shellQuote(*hostStatus) + "\n");
            hostScripts.push_back(*hostScript);
        }
        const int timeout = kCompileTimeoutMs + 2'000 * static_cast<int>(keys.size());
        const ChildResult run = runHostShellCommand(parallelJobsCommand(hostScripts), scratch_, timeout);
        for (size_t i = 0; i < keys.size(); ++i) {
            CompileResult& result = results[i];
            const Job& job = jobs[i];
            const int exitCode = std::filesystem::exists(job.status, ec) ? std::atoi(readText(job.status).c_str()) : -1;
            if (std::filesystem::exists(job.log, ec)) result.log = readText(job.log);
            if (exitCode == 0 && std::filesystem::exists(job.output, ec)) {
                result.bytecode = readFileBytes(job.output);
                result.ok = !result.bytecode.empty();
            }
            if (!result.ok && result.log.empty())
                result.log = exitCode < 0 ? "the compiler did not run: " + run.output
                                          : "the compiler failed with exit code " + std::to_string(exitCode);
        }
    } catch (const Error& e) {
        for (CompileResult& result : results) {
            result.ok = false;
            result.log = e.what();
        }
    }
    for (const Job& job : jobs)
        for (const auto& file : {job.wrapper, job.output, job.script, job.log, job.status}) std::filesystem::remove(file, ec);
    return results;
}

}  // namespace firmament
