// libFuzzer harness: the block-spec JSON parser (and the spec's JSON writer on what it accepts,
// which must parse back). Anything but a spec or a tubemesh::Error is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "engine/core/types.hpp"
#include "geom/builders/spec_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    tubemesh::geom::BlockSpec spec;
    try {
        spec = tubemesh::geom::parse_block_spec(text, "fuzz.json");
    } catch (const tubemesh::Error&) {
        return 0;
    }
    // What the writer prints must be a spec again; failing that is a bug.
    const std::string again = tubemesh::geom::block_spec_json(spec);
    try {
        (void)tubemesh::geom::parse_block_spec(again, "again.json");
    } catch (const tubemesh::Error&) {
        std::abort();
    }
    return 0;
}
