#pragma once
// Errors the program reports to the person before it exits with a non-zero code. Thrown
// where a problem is found, caught once in main(), printed as one line naming the problem.
#include <stdexcept>
#include <string>

namespace firmament {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace firmament
