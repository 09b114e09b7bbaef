#pragma once
// One kind of pre-computed tables for the parameters asked for last: the complete set in use,
// and a set being made that replaces it once complete (so the old tables draw while new ones
// are computed over several frames). A set is made from the cache when it holds the key's
// files, else computed; a computed set is written to the cache, and to the export folder when
// there is one. The key hashes everything that shapes the tables (TableFiles.h).
//
// `Computation` is a StagedComputation; the model's table files provide two overloads found by
// argument-dependent lookup:
//   std::string readTables(ID3D11DeviceContext*, Computation&, key, folder, prefix);  // "" or why not ("missing")
//   void writeTables(ID3D11Device*, ID3D11DeviceContext*, const Computation&, key, folder, prefix);  // throws Error
#include "core/Error.h"
#include "core/Log.h"
#include "gpu/GpuProfiler.h"
#include "gpu/ShaderLibrary.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace firmament {

// Where tables are kept between runs.
struct TableStorage {
    std::optional<std::filesystem::path> cacheFolder;   // none: no cache
    std::optional<std::filesystem::path> exportFolder;  // --export-luts: every new table set is written here
    std::filesystem::path mediaFolder = "media";        // tables shipped with the program (the cloud particle's scattering)
};

template <typename Computation>
class CachedTables {
public:
    // `name` starts the log lines ("atmosphere"); `passName` is the GPU profiler's name of the work.
    CachedTables(std::string name, std::string passName) : name_(std::move(name)), passName_(std::move(passName)) {}

    // Starts new tables when `key` is not the newest one asked for (made by `make()`, or read from
    // the cache); advances them by one unit of work, or finishes them when `finishNow`; once
    // complete, caches and exports them and puts them in use.
    template <typename Make>
    void update(ID3D11Device* device, ID3D11DeviceContext* context, ShaderLibrary& shaders, GpuProfiler& profiler, const TableStorage& storage,
                const std::string& key, Make&& make, bool finishNow) {
        const std::string& newest = pending_ ? pendingKey_ : currentKey_;
        if (newest != key) start(context, storage, key, make());
        if (!pending_) return;
        if (!pending_->done()) {
            auto pass = profiler.scope(passName_);
            if (finishNow) pending_->runAll(context, shaders);
            else pending_->stepInFrame(context, shaders);
        }
        if (pending_->done()) finish(device, context, storage);
    }

    const Computation* current() const { return current_.get(); }
    const Computation* pending() const { return pending_.get(); }

private:
    void start(ID3D11DeviceContext* context, const TableStorage& storage, const std::string& key, std::unique_ptr<Computation> tables) {
        if (current_) log::info(name_ + ": parameters or pre-computation shaders changed: new tables " + key);
        pending_ = std::move(tables);
        pendingKey_ = key;
        pendingFromCache_ = false;
        if (!storage.cacheFolder) return;
        const std::string why = readTables(context, *pending_, key, *storage.cacheFolder, key + "-");
        if (why.empty()) {
            pendingFromCache_ = true;
            log::info(name_ + ": tables " + key + " loaded from the cache in " + storage.cacheFolder->string());
        } else if (why != "missing") {
            log::warning(name_ + ": the cached tables cannot be used (" + why + "); computing them again");
        }
    }

    void finish(ID3D11Device* device, ID3D11DeviceContext* context, const TableStorage& storage) {
        if (storage.cacheFolder && !pendingFromCache_) {
            try {
                writeTables(device, context, *pending_, pendingKey_, *storage.cacheFolder, pendingKey_ + "-");
                log::info(name_ + ": tables " + pendingKey_ + " saved to the cache in " + storage.cacheFolder->string());
            } catch (const Error& e) {
                log::warning(name_ + ": the tables were not cached: " + e.what());
            }
        }
        if (storage.exportFolder) {
            writeTables(device, context, *pending_, pendingKey_, *storage.exportFolder, "");  // throws: the run fails
            log::info(name_ + ": tables exported to " + storage.exportFolder->string());
        }
        current_ = std::move(pending_);
        currentKey_ = pendingKey_;
    }

    std::string name_, passName_;
    std::unique_ptr<Computation> current_, pending_;
    std::string currentKey_, pendingKey_;
    bool pendingFromCache_ = false;
};

}  // namespace firmament
