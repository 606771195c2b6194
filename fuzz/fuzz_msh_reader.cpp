// libFuzzer harness: the Gmsh MSH reader on arbitrary bytes. Anything but a mesh or a
// tubemesh::Error (a crash, a sanitizer report, another exception) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/core/types.hpp"
#include "engine/io/msh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        (void)tubemesh::io::read_msh_bytes(bytes, "fuzz.msh");
    } catch (const tubemesh::Error&) {
    }
    return 0;
}
