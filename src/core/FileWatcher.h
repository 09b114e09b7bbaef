#pragma once
// Notices files that change on disk, by polling their write time and size (a few dozen
// shader files, a few times a second: cheaper and more dependable than change
// notifications, which editors that save by renaming defeat, and which Wine maps loosely).
#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

namespace firmament {

class FileWatcher {
public:
    void watch(const std::filesystem::path& file);  // remembers its state now (also when missing)
    std::vector<std::filesystem::path> poll();      // the watched files that changed since the last poll
    size_t size() const { return stamps_.size(); }

private:
    struct Stamp {
        bool exists = false;
        std::filesystem::file_time_type written{};
        std::uintmax_t size = 0;
        bool operator==(const Stamp&) const = default;
    };
    static Stamp stampOf(const std::filesystem::path& file);

    std::map<std::filesystem::path, Stamp> stamps_;
};

}  // namespace firmament
