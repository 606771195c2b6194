// libFuzzer harness: the batch manifest reader (JSON, block entries, options merged over the
// defaults). Anything but a manifest or a tubemesh::Error is a finding. Relative paths point
// into a folder that does not exist, so a block's input is never read.
#include <cstddef>
#include <cstdint>
#include <string>

#include "batch/manifest.hpp"
#include "engine/core/types.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const auto manifest = tubemesh::batch::parse_manifest(text, "/nonexistent-fuzz-folder/manifest.json");
        (void)manifest;
    } catch (const tubemesh::Error&) {
    }
    return 0;
}
