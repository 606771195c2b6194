#pragma once
// The message of the tubemesh::Error a callable throws, for tests that check what an error says.
#include <string>

#include "engine/core/types.hpp"

namespace tubemesh::testing {

// The message of the tubemesh::Error that `f` throws ("" when it throws none).
template <class F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace tubemesh::testing
