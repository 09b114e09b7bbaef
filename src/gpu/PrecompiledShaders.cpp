#include "gpu/PrecompiledShaders.h"

#include "core/Error.h"
#include "core/FileIO.h"

#include <fstream>

namespace firmament {

PrecompiledShaders::PrecompiledShaders(std::filesystem::path folder) : folder_(std::move(folder)) {
    std::error_code ec;
    if (!std::filesystem::is_directory(folder_, ec))
        throw Error("shader folder '" + folder_.string() + "' does not exist (build the project, or pass --shader-dir)");
    const auto manifest = folder_ / "manifest.txt";
    std::ifstream in(manifest);
    if (!in) throw Error("shader folder '" + folder_.string() + "' has no manifest.txt: it is not a built shader folder");
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const auto tab = line.find('\t');
        if (tab == std::string::npos) continue;
        if (line.compare(0, tab, "#source") == 0) {
            sourceRoot_ = std::filesystem::path(line.substr(tab + 1));
            continue;
        }
        if (line.compare(0, tab, "#cache") == 0) {
            cacheLauncher_ = line.substr(tab + 1);
            continue;
        }
        files_[line.substr(0, tab)] = line.substr(tab + 1);
    }
}

CompileResult PrecompiledShaders::compile(const ShaderKey& key) {
    CompileResult result;
    const auto it = files_.find(key.id());
    if (it == files_.end()) {
        result.log = "no precompiled permutation " + key.id() + " in " + (folder_ / "manifest.txt").string();
        return result;
    }
    try {
        result.bytecode = readFileBytes(folder_ / it->second);
        result.ok = !result.bytecode.empty();
        if (!result.ok) result.log = (folder_ / it->second).string() + " is empty";
    } catch (const Error& e) {
        result.log = e.what();
    }
    return result;
}

}  // namespace firmament
