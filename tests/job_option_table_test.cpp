// The option table (job/option_table.hpp) against README's option table and the front ends' names.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "batch/block_options.hpp"
#include "batch/sha256.hpp"
#include "engine/core/types.hpp"
#include "job/job_settings.hpp"
#include "job/option_table.hpp"

namespace tubemesh::job {
namespace {

std::string readme_table() {
    std::ifstream in(TUBEMESH_SOURCE_DIR "/README.md");
    std::stringstream text;
    text << in.rdbuf();
    const std::string all = text.str();
    const std::string begin = "<!-- option table: job/option_table.cpp -->\n", end = "<!-- end of option table -->";
    const std::size_t b = all.find(begin), e = all.find(end);
    if (b == std::string::npos || e == std::string::npos) return "";
    return all.substr(b + begin.size(), e - b - begin.size());
}

TEST(OptionTable, ReadmeTableIsTheTables) {
    // A blank line ends the table before the closing marker.
    EXPECT_EQ(readme_table(), option_table_markdown() + "\n")
        << "README.md's option table differs: put this between its markers:\n" << option_table_markdown();
}

TEST(OptionTable, EveryKeyAndFlagIsOneOption) {
    std::set<std::string> names;
    for (const OptionSpec& s : option_table()) {
        EXPECT_TRUE(names.insert(s.key).second) << s.key;
        for (const OptionAlias& a : s.aliases) EXPECT_TRUE(names.insert(a.name).second) << a.name;
        EXPECT_FALSE(s.help.empty()) << s.key;
        EXPECT_FALSE(s.default_text.empty()) << s.key;
    }
}

TEST(OptionTable, DefaultsAreTheEnginesAndTheManifestsKeysAreTheTables) {
    const JobSettings d = job_settings(nlohmann::json::object(), Naming::Keywords);
    const MeshOptions engine = mesh_options(MeshSettings{}, Naming::Keywords);
    const MeshOptions from_table = mesh_options(d.mesh, Naming::Keywords);
    EXPECT_EQ(from_table.local_ring, engine.local_ring);
    EXPECT_EQ(from_table.tets.slide_surface, engine.tets.slide_surface);
    EXPECT_EQ(from_table.sweep.radial_layers, engine.sweep.radial_layers);
    EXPECT_EQ(from_table.chordal, engine.chordal);
    const nlohmann::json manifest = batch::default_block_options();
    for (const OptionSpec& s : option_table())
        EXPECT_EQ(manifest.contains(s.key), (s.shown & kManifest) != 0) << s.key;
}

TEST(OptionTable, OlderSpellingsWorkInvertedWithAWarning) {
    std::vector<std::string> warnings;
    const nlohmann::json given = canonical_options({{"slide_surface", false}, {"local_ring", false}}, kManifest, "here",
                                                   [&](const std::string& w) { warnings.push_back(w); });
    EXPECT_EQ(given, nlohmann::json({{"fixed_surface", true}, {"global_ring", true}}));
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[0].find("is deprecated: use \"global_ring\""), std::string::npos) << warnings[0];
    const JobSettings s = job_settings(given, Naming::Keywords);
    EXPECT_FALSE(s.mesh.slide_surface);
    EXPECT_FALSE(s.mesh.local_ring);
}

TEST(OptionTable, TheOptionsHashKeepsItsFormerNames) {
    // A block's hash before the table: the former keys, slide_surface and local_ring among them.
    nlohmann::json before = batch::default_block_options();
    for (const char* added : {"economy", "assembly", "glue_tolerance", "msh_ascii", "inp_family", "inp_pyramid", "scale_free"})
        before.erase(added);
    before.erase("fixed_surface");
    before.erase("global_ring");
    before["slide_surface"] = true;
    before["local_ring"] = true;
    before.erase("time_limit");
    for (auto& [key, value] : before.items())
        if (value.is_number()) value = value.get<double>();
    before["tubemesh"] = TUBEMESH_VERSION;
    EXPECT_EQ(batch::options_hash(batch::default_block_options()), batch::sha256_hex(before.dump()));
    nlohmann::json economy = batch::default_block_options();
    economy["economy"] = true;
    EXPECT_NE(batch::options_hash(economy), batch::options_hash(batch::default_block_options()));
}

TEST(OptionTable, EconomySetsOnlyWhatIsNotGiven) {
    const JobSettings e = job_settings({{"economy", true}, {"layers", 3}}, Naming::Keywords);
    EXPECT_EQ(e.mesh.layers, 3);
    EXPECT_EQ(e.mesh.circumferential, kEconomy.circumferential);
    EXPECT_EQ(e.mesh.local_ring, kEconomy.local_ring);
    EXPECT_EQ(job_settings({{"economy", true}, {"global_ring", false}}, Naming::Keywords).mesh.local_ring, true);
}

}  // namespace
}  // namespace tubemesh::job
