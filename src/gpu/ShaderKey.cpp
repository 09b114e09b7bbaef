#include "gpu/ShaderKey.h"

#include "core/Error.h"

#include <algorithm>

namespace firmament {

std::string ShaderKey::id() const {
    std::vector<std::string> sorted = defines;
    std::sort(sorted.begin(), sorted.end());
    std::string out = file + "|" + entry + "|" + profile + "|";
    for (size_t i = 0; i < sorted.size(); ++i) out += (i ? "," : "") + sorted[i];
    return out;
}

ShaderStage ShaderKey::stage() const {
    const std::string prefix = profile.substr(0, 3);
    if (prefix == "vs_") return ShaderStage::Vertex;
    if (prefix == "ps_") return ShaderStage::Pixel;
    if (prefix == "cs_") return ShaderStage::Compute;
    if (prefix == "gs_") return ShaderStage::Geometry;
    if (prefix == "hs_") return ShaderStage::Hull;
    if (prefix == "ds_") return ShaderStage::Domain;
    throw Error("shader " + file + ": unknown profile '" + profile + "'");
}

}  // namespace firmament
