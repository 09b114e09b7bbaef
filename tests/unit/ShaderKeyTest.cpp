// Shader permutation keys: the string must match what cmake/FirmamentShaders.cmake writes
// into manifest.txt ("file|entry|profile|A=1,B=2", defines sorted).
#include "core/Error.h"
#include "gpu/ShaderKey.h"

#include <gtest/gtest.h>

namespace firmament {
namespace {

TEST(ShaderKey, IdSortsDefinesLikeTheBuild) {
    const ShaderKey key{"atmosphere/sky.hlsl", "ps_main", "ps_5_0", {"Z_LAST=1", "A_FIRST=2"}};
    EXPECT_EQ(key.id(), "atmosphere/sky.hlsl|ps_main|ps_5_0|A_FIRST=2,Z_LAST=1");
    EXPECT_EQ((ShaderKey{"a.hlsl", "main", "cs_5_0", {}}.id()), "a.hlsl|main|cs_5_0|");
}

TEST(ShaderKey, StageComesFromTheProfile) {
    EXPECT_EQ((ShaderKey{"a.hlsl", "main", "vs_5_0", {}}.stage()), ShaderStage::Vertex);
    EXPECT_EQ((ShaderKey{"a.hlsl", "main", "ps_5_0", {}}.stage()), ShaderStage::Pixel);
    EXPECT_EQ((ShaderKey{"a.hlsl", "main", "cs_5_0", {}}.stage()), ShaderStage::Compute);
    EXPECT_EQ((ShaderKey{"a.hlsl", "main", "gs_5_0", {}}.stage()), ShaderStage::Geometry);
    EXPECT_THROW((ShaderKey{"a.hlsl", "main", "xx_5_0", {}}.stage()), Error);
}

}  // namespace
}  // namespace firmament
