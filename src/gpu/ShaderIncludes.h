#pragma once
// The files a shader is made of: its source and everything it #includes, transitively.
// Includes are written relative to the shader root (the convention every backend follows),
// so the lookup is plain text scanning; a missing include is listed too, to be watched.
#include <filesystem>
#include <string>
#include <vector>

namespace firmament {

// Paths relative to `root`, the source first.
std::vector<std::string> shaderSourceFiles(const std::filesystem::path& root, const std::string& file);

}  // namespace firmament
