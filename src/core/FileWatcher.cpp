#include "core/FileWatcher.h"

namespace firmament {

FileWatcher::Stamp FileWatcher::stampOf(const std::filesystem::path& file) {
    std::error_code ec;
    Stamp stamp;
    stamp.written = std::filesystem::last_write_time(file, ec);
    if (ec) return {};
    stamp.size = std::filesystem::file_size(file, ec);
    stamp.exists = !ec;
    return stamp;
}

void FileWatcher::watch(const std::filesystem::path& file) {
    if (!stamps_.count(file)) stamps_[file] = stampOf(file);
}

std::vector<std::filesystem::path> FileWatcher::poll() {
    std::vector<std::filesystem::path> changed;
    for (auto& [file, stamp] : stamps_) {
        const Stamp now = stampOf(file);
        if (now == stamp) continue;
        stamp = now;
        changed.push_back(file);
    }
    return changed;
}

}  // namespace firmament
