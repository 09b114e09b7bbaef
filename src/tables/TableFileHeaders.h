#pragma once
// The part of the table cache that needs no GPU (both atmosphere models' look-up tables, the
// terrain's height field, the clouds' tables): the key of data made on the CPU and the header
// check that decides whether a cached file fits. Every cache file is written by writeExr,
// which replaces a file whole or not at all (core/FileIO.h), so no reader sees half of one.
#include "core/ExrImage.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace firmament {

// FNV-1a, 64 bits, continuing from `hash`: stable across builds and platforms, unlike std::hash.
constexpr std::uint64_t kFnv1aStart = 0xcbf29ce484222325ull;
std::uint64_t fnv1a(const void* data, size_t size, std::uint64_t hash = kFnv1aStart);
// A hash as the 16 hexadecimal digits that cache file names carry.
std::string hexKey(std::uint64_t hash);

// The key of data made on the CPU alone (the terrain's height field): the description's hash.
std::string tableKey(const std::string& description);

// Empty when the header's firmament.lut.key is `key` and the file is width x height; else why not.
std::string checkTableHeader(const ExrAttributes& attributes, const std::string& key, int width, int height, int fileWidth, int fileHeight);

}  // namespace firmament
