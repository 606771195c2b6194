#pragma once
// Index type, sentinels and the one exception type of the engine.
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace tubemesh {

// 32-bit indices everywhere: a 2-core machine meshes at most a few hundred million entities.
using index_t = std::uint32_t;

// "No node / no element / no neighbour": one named value instead of a scattered -1.
inline constexpr index_t kNoIndex = std::numeric_limits<index_t>::max();

// Errors a user can act on: the message names what is wrong and, where it helps, what to do.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace tubemesh
