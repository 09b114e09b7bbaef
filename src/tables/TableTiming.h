#pragma once
// How long a set of tables takes to compute, against how long it takes to load from the cache:
// the benchmark's record of what the cache saves (measured by timeTables, tables/TimeTables.h).
#include <string>

namespace firmament {

struct TableTiming {
    std::string name;        // which tables ("Yusov 2013", ...)
    std::string key;         // their cache key
    double computeSeconds = 0.0;
    double cacheLoadSeconds = 0.0;
};

}  // namespace firmament
