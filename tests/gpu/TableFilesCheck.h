#pragma once
// The checks both atmosphere models' table files must pass (YusovTableFiles,
// BrunetonTableFiles): what is written reads back bit for bit into fresh tables; missing files,
// another key, other sizes and a truncated file are each refused with a reason, and a refused
// read leaves the tables to be computed.
#include "core/FileIO.h"
#include "gpu/Readback.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace firmament::test {

// `contents` reads every table of a pre-computation back; `bigger` are parameters with other
// sizes; `truncatedFile` is the file name (after the "k-" prefix) to cut in half.
template <typename Precomputation, typename Parameters>
void checkTableFiles(ID3D11Device* device, ID3D11DeviceContext* context, const Precomputation& computed, const std::string& key,
                     const Parameters& bigger, const std::string& truncatedFile,
                     const std::function<std::vector<std::vector<std::uint8_t>>(const Precomputation&)>& contents) {
    EXPECT_EQ(key.size(), 16u);
    const auto folder = std::filesystem::temp_directory_path() / ("firmament-table-files-" + truncatedFile);
    std::filesystem::remove_all(folder);
    writeTables(device, context, computed, key, folder, "k-");

    Precomputation loaded(device, computed.parameters());
    EXPECT_FALSE(loaded.done());
    EXPECT_EQ(readTables(context, loaded, key, folder, "k-"), "");
    EXPECT_TRUE(loaded.done());
    EXPECT_EQ(contents(loaded), contents(computed));

    Precomputation other(device, computed.parameters());
    EXPECT_EQ(readTables(context, other, key, folder, "absent-"), "missing");
    EXPECT_NE(readTables(context, other, "0123456789abcdef", folder, "k-").find("key differs"), std::string::npos);
    Precomputation resized(device, bigger);
    EXPECT_NE(readTables(context, resized, key, folder, "k-").find("not"), std::string::npos);
    EXPECT_FALSE(resized.done());
    const auto path = folder / ("k-" + truncatedFile);
    auto bytes = readFileBytes(path);
    bytes.resize(bytes.size() / 2);
    writeFileBytes(path, bytes);
    const std::string why = readTables(context, other, key, folder, "k-");
    EXPECT_NE(why.find("k-" + truncatedFile), std::string::npos) << why;
    EXPECT_FALSE(other.done());
    std::filesystem::remove_all(folder);
}

}  // namespace firmament::test
