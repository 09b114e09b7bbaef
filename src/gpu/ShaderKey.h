#pragma once
// Identifies one shader permutation: source file (relative to the shader root), entry
// point, profile and defines. id() is the string the build writes into manifest.txt
// (cmake/FirmamentShaders.cmake): "file|entry|profile|A=1,B=2", defines sorted.
#include <string>
#include <vector>

namespace firmament {

enum class ShaderStage { Vertex, Pixel, Compute, Geometry, Hull, Domain };

struct ShaderKey {
    std::string file;
    std::string entry = "main";
    std::string profile;
    std::vector<std::string> defines;  // "NAME=VALUE"

    std::string id() const;
    ShaderStage stage() const;  // from the profile's prefix; throws Error if unknown
};

}  // namespace firmament
