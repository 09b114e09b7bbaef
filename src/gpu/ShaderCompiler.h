#pragma once
// Where shader bytecode comes from. One interface for every backend: the DXBC compiled at
// build time (PrecompiledShaders), and, for hot reload, D3DCompile or an external compiler
// process that compile the HLSL on disk.
#include "gpu/ShaderKey.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
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

    // Several permutations at once, results in the keys' order. By default a few threads
    // call compile(); a backend that starts a process per shader batches them instead.
    // compile() must then be safe to call from several threads, as every backend's is.
    virtual std::vector<CompileResult> compileAll(const std::vector<ShaderKey>& keys) {
        std::vector<CompileResult> results(keys.size());
        std::atomic<size_t> next{0};
        const auto work = [&] {
            for (size_t i = next++; i < keys.size(); i = next++) results[i] = compile(keys[i]);
        };
        const size_t workers = std::min<size_t>(keys.size(), std::max(1u, std::thread::hardware_concurrency()));
        std::vector<std::thread> threads;
        for (size_t t = 1; t < workers; ++t) threads.emplace_back(work);
        work();
        for (auto& thread : threads) thread.join();
        return results;
    }
};

}  // namespace firmament
