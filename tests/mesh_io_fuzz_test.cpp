// Corrupt MSH files must give tubemesh::Error naming a line or byte offset, never a crash,
// a hang, a huge allocation or another exception. Every truncation and hundreds of byte
// corruptions of valid files, both encodings. Run it under the asan preset as well.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

#include "engine/io/mesh_io.hpp"
#include "engine/io/msh_reader.hpp"
#include "tests/support/mesh_io_samples.hpp"
#include "tests/support/process.hpp"
#include "tests/support/sample_meshes.hpp"

namespace tubemesh {
namespace {

std::string msh_bytes(const HybridMesh& mesh, MshEncoding encoding) {
    testing::TempDir dir;
    write_msh(mesh, dir / "m.msh", encoding);
    return testing::read_text(dir / "m.msh");
}

enum class Outcome { Read, Error };

// "fuzz.msh: line N: ..." or "fuzz.msh: byte offset N: ...".
bool names_a_place(const std::string& message) {
    for (const std::string prefix : {"fuzz.msh: line ", "fuzz.msh: byte offset "}) {
        if (message.rfind(prefix, 0) != 0) continue;
        std::size_t i = prefix.size();
        const std::size_t digits = i;
        while (i < message.size() && message[i] >= '0' && message[i] <= '9') ++i;
        return i > digits && message.compare(i, 2, ": ") == 0;
    }
    return false;
}

// Reads corrupted bytes; a read mesh must be consistent, an error must name its place.
Outcome read_corrupted(const std::string& bytes, const std::string& what) {
    try {
        const HybridMesh m = io::read_msh_bytes(bytes, "fuzz.msh");
        m.validate_layout();
        return Outcome::Read;
    } catch (const Error& e) {
        EXPECT_TRUE(names_a_place(e.what())) << what << ": " << e.what();
        return Outcome::Error;
    } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": not a tubemesh::Error: " << e.what();
    }
    return Outcome::Error;
}

class MshFuzz : public ::testing::TestWithParam<MshEncoding> {
protected:
    std::string valid() const {
        HybridMesh mesh = testing::conforming_patch();
        mesh.region_names[0] = "hex ring";  // a name with a space, for the quoting code
        return msh_bytes(mesh, GetParam());
    }
};

// A file cut anywhere before its last section ends is an error; only the final line break
// may go missing.
TEST_P(MshFuzz, EveryTruncation) {
    const std::string bytes = valid();
    const std::size_t complete = bytes.rfind("$EndElements") + std::string("$EndElements").size();
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        const Outcome o = read_corrupted(bytes.substr(0, n), "truncated to " + std::to_string(n));
        EXPECT_EQ(o == Outcome::Read, n >= complete) << "truncated to " << n;
    }
}

// Single and multiple byte flips, and runs of 0xff / 0x00 that turn counts and tags into huge
// or zero values; on the patch and on a larger mixed grid.
TEST_P(MshFuzz, ByteCorruptions) {
    HybridMesh grid = testing::mixed_grid(2);
    for (const std::string& bytes : {valid(), msh_bytes(grid, GetParam())}) {
        std::mt19937 random(GetParam() == MshEncoding::Ascii ? 1 : 2);
        std::uniform_int_distribution<std::size_t> position(0, bytes.size() - 1);
        std::uniform_int_distribution<int> byte(1, 255);
        int errors = 0;
        const int variants = 2000;
        for (int v = 0; v < variants; ++v) {
            std::string bad = bytes;
            const std::size_t at = position(random);
            switch (v % 3) {
                case 0: bad[at] = static_cast<char>(bad[at] ^ byte(random)); break;
                case 1:
                    for (int k = 0; k < 4; ++k) {
                        const std::size_t p = position(random);
                        bad[p] = static_cast<char>(bad[p] ^ byte(random));
                    }
                    break;
                default: {
                    const char fill = (v / 3) % 2 == 0 ? '\xff' : '\0';
                    for (std::size_t p = at; p < std::min(bad.size(), at + 8); ++p) bad[p] = fill;
                }
            }
            errors += read_corrupted(bad, "variant " + std::to_string(v)) == Outcome::Error;
        }
        // Most corruptions must be caught; some (a coordinate digit) make another valid mesh.
        EXPECT_GT(errors, variants / 4);
    }
}

// Counts that promise more than the file holds must not be trusted with an allocation.
TEST_P(MshFuzz, HugeCountsAreRejectedBeforeAllocating) {
    std::string bytes = valid();
    const std::size_t nodes = bytes.find("$Nodes\n") + 7;
    if (GetParam() == MshEncoding::Binary) {
        const std::uint64_t huge = std::uint64_t{1} << 60;
        bytes.replace(nodes + 8, 8, reinterpret_cast<const char*>(&huge), 8);
    } else {
        bytes.replace(nodes, bytes.find('\n', nodes) - nodes, "1 1000000000000 1 13");
    }
    const std::string message = [&] {
        try {
            io::read_msh_bytes(bytes, "fuzz.msh");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    }();
    EXPECT_NE(message.find("node count"), std::string::npos) << message;
    EXPECT_NE(message.find("is more than the rest of the file can hold"), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(Encodings, MshFuzz, ::testing::Values(MshEncoding::Ascii, MshEncoding::Binary),
                         [](const auto& info) { return info.param == MshEncoding::Ascii ? "Ascii" : "Binary"; });

}  // namespace
}  // namespace tubemesh
